#pragma once
// bsc::trace_buffer: the bounded ring a bsc::tracer writes its frames into and a program drains
// to a file or a socket. It never allocates (the storage is the caller's) and never blocks: a
// frame that does not fit is dropped whole and counted, and an overflow record says so when
// room returns, so that a reader sees the loss (docs/trace.md).
//
//   std::array<std::byte, 4096> storage;
//   bsc::trace_buffer buffer{storage};
//   ...
//   std::array<std::byte, 512> chunk;
//   while (auto n = buffer.read(chunk)) file.write(reinterpret_cast<char const*>(chunk.data()), n);
//
// One thread may write (the machine's) while one other reads (a server's): the positions are
// atomic, each side moves its own.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

#include <bsc/detail/trace/format.hpp>

namespace bsc {

/// A ring of trace frames over storage the caller owns (which must outlive it).
class trace_buffer {
public:
    /// Frames go into `storage`; a frame longer than storage.size() is always dropped.
    explicit trace_buffer(std::span<std::byte> storage) noexcept : storage_(storage) {}

    trace_buffer(trace_buffer const&) = delete;
    trace_buffer& operator=(trace_buffer const&) = delete;

    /// Appends one frame of type `type` with `payload` (at most 255 bytes, the rest is cut), or
    /// drops it if it does not fit. Either way it takes the next sequence number. After a drop,
    /// the next frame that fits is preceded by an overflow record with the count of drops.
    /// Returns whether the frame was written.
    bool write(detail::trace::record_type type, std::span<std::byte const> payload) noexcept {
        namespace t = detail::trace;
        if (payload.size() > t::max_payload) payload = payload.first(t::max_payload);
        std::size_t const needed = t::header_size + payload.size() + t::trailer_size;
        std::size_t constexpr overflow_frame = t::header_size + 8 + t::trailer_size;
        std::size_t const room = storage_.size() -
                                 used(head_.load(std::memory_order_relaxed), tail_.load(std::memory_order_acquire));
        if (overflow_pending_) {
            if (room < overflow_frame + needed) return drop();
            std::byte count[8];
            t::put(count, dropped_.load(std::memory_order_relaxed));
            append(t::record_type::overflow, count);
            overflow_pending_ = false;
        } else if (room < needed) {
            return drop();
        }
        append(type, payload);
        return true;
    }

    /// Moves the oldest bytes, up to out.size(), into `out`; returns how many. Frames may be cut
    /// between two reads: a reader joins the pieces.
    std::size_t read(std::span<std::byte> out) noexcept {
        std::size_t const tail = tail_.load(std::memory_order_relaxed);
        std::size_t const available = used(head_.load(std::memory_order_acquire), tail);
        std::size_t const n = available < out.size() ? available : out.size();
        if (n > 0) {
            std::size_t const at = index(tail);
            std::size_t const first = n < storage_.size() - at ? n : storage_.size() - at;  // up to the ring's end
            std::memcpy(out.data(), storage_.data() + at, first);
            std::memcpy(out.data() + first, storage_.data(), n - first);
        }
        tail_.store(advance(tail, n), std::memory_order_release);
        return n;
    }

    /// The bytes waiting to be read.
    std::size_t size() const noexcept {
        return used(head_.load(std::memory_order_acquire), tail_.load(std::memory_order_acquire));
    }
    /// The storage's size.
    std::size_t capacity() const noexcept { return storage_.size(); }
    /// The frames dropped for want of room, since construction.
    std::uint64_t dropped() const noexcept { return dropped_.load(std::memory_order_relaxed); }
    /// The frames written, overflow records included, since construction.
    std::uint64_t written() const noexcept { return written_.load(std::memory_order_relaxed); }

private:
    bool drop() noexcept {
        ++sequence_;
        dropped_.store(dropped_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
        overflow_pending_ = true;
        return false;
    }

    // The frame is made whole first, so that its checksum runs over one array and it goes into
    // the ring in at most two copies.
    void append(detail::trace::record_type type, std::span<std::byte const> payload) noexcept {
        namespace t = detail::trace;
        std::byte frame[t::max_frame];
        frame[0] = t::sync;
        frame[1] = static_cast<std::byte>(type);
        t::put(frame + 2, sequence_++);
        frame[4] = static_cast<std::byte>(payload.size());
        if (!payload.empty()) std::memcpy(frame + t::header_size, payload.data(), payload.size());
        std::size_t const body = t::header_size + payload.size();
        t::put(frame + body, t::crc(std::span<std::byte const>{frame + 1, body - 1}));
        std::size_t const size = body + t::trailer_size;
        std::size_t const head = head_.load(std::memory_order_relaxed);
        std::size_t const at = index(head);
        std::size_t const first = size < storage_.size() - at ? size : storage_.size() - at;
        std::memcpy(storage_.data() + at, frame, first);
        std::memcpy(storage_.data(), frame + first, size - first);
        head_.store(advance(head, size), std::memory_order_release);
        written_.store(written_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
    }

    // Positions run over twice the storage's size, so that a full ring (head a lap ahead of tail)
    // differs from an empty one, and never wrap the size type, whatever its width.
    std::size_t used(std::size_t head, std::size_t tail) const noexcept {
        return head >= tail ? head - tail : head + 2 * storage_.size() - tail;
    }
    std::size_t index(std::size_t position) const noexcept {
        return position < storage_.size() ? position : position - storage_.size();
    }
    std::size_t advance(std::size_t position, std::size_t n) const noexcept {
        std::size_t const next = position + n;  // n <= the storage's size: no overflow below twice it
        return next < 2 * storage_.size() ? next : next - 2 * storage_.size();
    }

    std::span<std::byte> storage_;
    std::atomic<std::size_t> head_{0};  // where the writer writes next, in [0, 2 * size): moved by the writer only
    std::atomic<std::size_t> tail_{0};  // where the reader reads next, in [0, 2 * size): moved by the reader only
    std::atomic<std::uint64_t> dropped_{0};
    std::atomic<std::uint64_t> written_{0};
    std::uint16_t sequence_ = 0;
    bool overflow_pending_ = false;
};

}  // namespace bsc
