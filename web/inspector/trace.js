// The trace stream's reader for the page and for Node: the same frames, dictionary, counters and
// record text as bsc::trace_reader (include/bsc/trace_reader.hpp), whose frame layout is in
// include/bsc/detail/trace/format.hpp. It takes any bytes and never throws on them: every length
// and number is checked before it is used.
//
// Times, delays and values are BigInt, as the stream's i64 and u64 fields do not fit a Number.
//
// A classic script, not a module: browsers load no module script into a page opened from
// file://. Its API is the one global BscTrace (and module.exports where there is a module).

(function () {
  'use strict';

  const RecordType = Object.freeze({
    hello: 0x01,
    state: 0x02,
    event: 0x03,
    member: 0x04,
    row: 0x05,
    configuration: 0x06,
    dispatch: 0x10,
    cycle: 0x11,
    cycleEnd: 0x12,
    exit: 0x13,
    entry: 0x14,
    transition: 0x15,
    deferral: 0x16,
    values: 0x20,
    overflow: 0x30,
  });

  const typeNames = new Map(Object.entries(RecordType).map(([name, type]) => [type, name]));

  /** No parent, an internal transition's target, an unnamed event. */
  const NONE = 0xffff;
  const EVENTLESS = 0xfffe;
  /** A transition on a timeout: its record carries the delay. */
  const TIMEOUT = 0xfffd;
  /** The chart's root state; 0 is the implicit top above it. */
  const ROOT = 1;

  /** State kinds, as bsc::detail::kind. */
  const StateKind = Object.freeze({ top: 0, basic: 1, final: 2, composite: 3, parallel: 4, history: 5 });
  /** Member kinds: how a values record's bits read. */
  const MemberKind = Object.freeze({ bool: 0, signed: 1, unsigned: 2, real: 3 });

  const SYNC = 0xb5;
  const HEADER = 5;
  const TRAILER = 2;

  // CRC-16/CCITT-FALSE, one table lookup a byte.
  const crcTable = (() => {
    const t = new Uint16Array(256);
    for (let i = 0; i < 256; ++i) {
      let c = i << 8;
      for (let b = 0; b < 8; ++b) c = c & 0x8000 ? ((c << 1) ^ 0x1021) & 0xffff : (c << 1) & 0xffff;
      t[i] = c;
    }
    return t;
  })();

  /** The CRC-16/CCITT-FALSE of bytes[from, to). */
  function crc16(bytes, from = 0, to = bytes.length, start = 0xffff) {
    let crc = start;
    for (let i = from; i < to; ++i) crc = ((crc << 8) & 0xffff) ^ crcTable[((crc >> 8) ^ bytes[i]) & 0xff];
    return crc;
  }

  /** "3s", "250ms", "20us" or "7ns": the largest unit that divides the duration (detail::delay_label). */
  function delayLabel(ns) {
    const n = BigInt(ns);
    if (n % 1000000000n === 0n) return `${n / 1000000000n}s`;
    if (n % 1000000n === 0n) return `${n / 1000000n}ms`;
    if (n % 1000n === 0n) return `${n / 1000n}us`;
    return `${n}ns`;
  }

  // A double as std::to_chars writes it without a format: the shortest digits that read back the
  // same, in fixed or scientific notation, whichever is shorter (fixed on a tie). JavaScript's own
  // String(x) picks its notation by the exponent instead, so it differs for 1e-5 or 1e21.
  function doubleText(x) {
    if (Number.isNaN(x)) return 'nan';
    if (x === Infinity) return 'inf';
    if (x === -Infinity) return '-inf';
    if (x === 0) return Object.is(x, -0) ? '-0' : '0';
    const sign = x < 0 ? '-' : '';
    const [mantissa, exponent] = Math.abs(x).toExponential().split('e');
    const digits = mantissa.replace('.', '');
    const e = Number(exponent);
    const n = digits.length;
    let fixed;
    if (e >= n - 1) fixed = digits + '0'.repeat(e - n + 1);
    else if (e >= 0) fixed = `${digits.slice(0, e + 1)}.${digits.slice(e + 1)}`;
    else fixed = `0.${'0'.repeat(-e - 1)}${digits}`;
    const exp = Math.abs(e) < 10 ? `0${Math.abs(e)}` : `${Math.abs(e)}`;
    const scientific = `${digits[0]}${n > 1 ? `.${digits.slice(1)}` : ''}e${e < 0 ? '-' : '+'}${exp}`;
    return sign + (scientific.length < fixed.length ? scientific : fixed);
  }

  const f64 = new DataView(new ArrayBuffer(8));

  /** The dictionary's parts, by number; names "#n" where none was given. */
  class TraceDictionary {
    constructor() {
      this.version = 0; // the hello's format version (0: no hello read)
      this.chart = '';
      this.states = []; // {name, parent, kind}
      this.events = []; // names
      this.rows = []; // {source, target, trigger, flags, label}; only transitions have a label
      this.members = []; // {name, kind, width}
    }

    stateName(n) {
      const s = this.states[n];
      return s && s.name ? s.name : `#${n}`;
    }
    eventName(n) {
      const e = this.events[n];
      return e ? e : `#${n}`;
    }
    memberName(n) {
      const m = this.members[n];
      return m && m.name ? m.name : `#${n}`;
    }

    /** A member's value (bits, a BigInt) as text, by its kind: "true", "-3", "42", "0.5". */
    valueText(member, bits) {
      const m = this.members[member];
      const kind = m ? m.kind : MemberKind.unsigned;
      const width = m ? m.width : 64;
      let v = BigInt.asUintN(64, BigInt(bits));
      if (kind === MemberKind.bool && v <= 1n) return v ? 'true' : 'false';
      if (kind === MemberKind.real) {
        f64.setBigUint64(0, v, true);
        const x = f64.getFloat64(0, true);
        // A NaN's sign is lost in a Number, but std::to_chars writes it.
        if (Number.isNaN(x)) return v >> 63n ? '-nan' : 'nan';
        return doubleText(x);
      }
      if (kind === MemberKind.signed) {
        // Sign-extended from the member's width, as the C++ reader does.
        if (width > 0 && width < 64 && (v >> BigInt(width - 1)) & 1n) v = BigInt.asUintN(64, v | (~0n << BigInt(width)));
        return BigInt.asIntN(64, v).toString();
      }
      return v.toString();
    }
  }

  // Fills a sparse vector with defaults up to index i, as std::vector::resize does in the C++
  // reader, so that every number below a named one has an entry.
  function at(list, i, make) {
    while (list.length <= i) list.push(make());
    return list[i];
  }

  const newState = () => ({ name: '', parent: NONE, kind: 0 });
  const newRow = () => ({ source: NONE, target: NONE, trigger: NONE, flags: 0, label: '' });
  const newMember = () => ({ name: '', kind: 0, width: 0 });
  const textDecoder = new TextDecoder('utf-8');

  /** Reads the frames out of the bytes fed to it, in pieces of any size. */
  class TraceReader {
    constructor() {
      this.pending = new Uint8Array(4096);
      this.finished = false; // no more bytes will come
      this.start = 0; // the first unread byte of pending
      this.end = 0; // one past the last byte fed
      this.dictionary = new TraceDictionary();
      this.time = 0n;
      this.frames = 0; // frames whose checksum held
      this.missing = 0; // frames the sequence numbers say were lost
      this.skippedBytes = 0; // bytes that started no valid frame
      this.malformed = 0; // checked frames of an unknown type or a payload that does not fit it
      this.nextSequence = 0;
      this.sequenced = false;
    }

    /** Appends bytes of the stream: a Uint8Array, an ArrayBuffer, any typed array or an array of numbers. */
    feed(bytes) {
      let input;
      if (bytes instanceof Uint8Array) input = bytes;
      else if (bytes instanceof ArrayBuffer) input = new Uint8Array(bytes);
      else if (ArrayBuffer.isView(bytes)) input = new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength);
      else if (Array.isArray(bytes)) input = Uint8Array.from(bytes, (b) => Number(b) & 0xff);
      else return;
      if (input.length === 0) return;
      const unread = this.end - this.start;
      if (unread + input.length > this.pending.length - this.start) {
        // Move the unread bytes to the front, and grow only if they still do not fit.
        let size = this.pending.length;
        while (size < unread + input.length) size *= 2;
        if (size === this.pending.length) {
          this.pending.copyWithin(0, this.start, this.end);
        } else {
          const grown = new Uint8Array(size);
          grown.set(this.pending.subarray(this.start, this.end));
          this.pending = grown;
        }
        this.start = 0;
        this.end = unread;
      }
      this.pending.set(input, this.end);
      this.end += input.length;
    }

    /**
     * Says that no more bytes will come (a whole file): a frame begun at the end can no longer be
     * completed, so next() skips its first byte and reads on instead of waiting.
     */
    finish() {
      this.finished = true;
    }

    /** The next whole frame whose checksum holds as a record, or null until more bytes are fed. */
    next() {
      const p = this.pending;
      for (;;) {
        while (this.start < this.end && p[this.start] !== SYNC) this.skip();
        if (this.end - this.start < HEADER) {
          if (!this.finished || this.start === this.end) return null;
          this.skip();
          continue;
        }
        const f = this.start;
        const length = p[f + 4];
        const size = HEADER + length + TRAILER;
        if (this.end - f < size) {
          if (!this.finished) return null;
          this.skip();
          continue;
        }
        const expected = p[f + HEADER + length] | (p[f + HEADER + length + 1] << 8);
        if (crc16(p, f + 1, f + HEADER + length) !== expected) {
          this.skip();
          continue;
        }
        this.start += size;
        ++this.frames;
        const sequence = p[f + 2] | (p[f + 3] << 8);
        if (this.sequenced) this.missing += (sequence - this.nextSequence) & 0xffff;
        this.nextSequence = (sequence + 1) & 0xffff;
        this.sequenced = true;
        // A copy, so that later feeds that move the buffer leave the record's bytes alone.
        const record = this.decode(p[f + 1], sequence, p.slice(f + HEADER, f + HEADER + length));
        if (record) return record;
        ++this.malformed;
      }
    }

    skip() {
      ++this.start;
      ++this.skippedBytes;
    }

    // The record a checked frame holds, with the dictionary updated, or null if the payload does
    // not fit its type.
    decode(type, sequence, payload) {
      const n = payload.length;
      const view = new DataView(payload.buffer, payload.byteOffset, n);
      const u16 = (i) => view.getUint16(i, true);
      const i64 = (i) => view.getBigInt64(i, true);
      const text = (from) => textDecoder.decode(payload.subarray(from));
      const d = this.dictionary;
      const r = {
        type,
        typeName: typeNames.get(type) ?? 'unknown',
        sequence,
        time: this.time, // the record's own for dispatch, cycle and values; the last one read otherwise
        state: NONE,
        source: NONE,
        target: NONE,
        event: NONE,
        row: NONE,
        member: NONE,
        delay: 0n,
        dropped: 0n,
        values: [],
        active: [], // configuration: the active states it lists
        begins: false, // configuration: whether they begin one, or add to the last record's
      };
      switch (type) {
        case RecordType.hello:
          if (n < 7) return null;
          this.dictionary = new TraceDictionary();
          this.dictionary.version = payload[0];
          this.dictionary.chart = r.chart = text(7);
          return r;
        case RecordType.row: {
          if (n < 9) return null;
          r.row = u16(0);
          const row = at(d.rows, r.row, newRow);
          row.source = u16(2);
          row.target = u16(4);
          row.trigger = u16(6);
          row.flags = payload[8];
          row.label = text(9);
          return r;
        }
        case RecordType.state: {
          if (n < 5) return null;
          r.state = u16(0);
          const s = at(d.states, r.state, newState);
          s.parent = u16(2);
          s.kind = payload[4];
          s.name = text(5);
          return r;
        }
        case RecordType.event:
          if (n < 2) return null;
          r.event = u16(0);
          at(d.events, r.event, () => '');
          d.events[r.event] = text(2);
          return r;
        case RecordType.member: {
          if (n < 4) return null;
          r.member = u16(0);
          const m = at(d.members, r.member, newMember);
          m.kind = payload[2];
          m.width = payload[3];
          m.name = text(4);
          return r;
        }
        case RecordType.configuration:
          if (n < 1 || (n - 1) % 2 !== 0 || payload[0] > 1) return null;
          r.begins = payload[0] === 1;
          for (let i = 1; i < n; i += 2) r.active.push(u16(i));
          return r;
        case RecordType.dispatch:
          if (n !== 10) return null;
          this.time = r.time = i64(0);
          r.event = u16(8);
          return r;
        case RecordType.cycle:
          if (n !== 8) return null;
          this.time = r.time = i64(0);
          return r;
        case RecordType.cycleEnd:
          return n === 0 ? r : null;
        case RecordType.exit:
        case RecordType.entry:
          if (n !== 2) return null;
          r.state = u16(0);
          return r;
        case RecordType.transition:
          if (n !== 8 && n !== 16) return null;
          r.row = u16(0);
          r.source = u16(2);
          r.target = u16(4);
          r.event = u16(6);
          if ((n === 16) !== (r.event === TIMEOUT)) return null;
          if (n === 16) r.delay = i64(8);
          return r;
        case RecordType.deferral:
          if (n !== 4) return null;
          r.state = u16(0);
          r.event = u16(2);
          return r;
        case RecordType.values:
          if (n < 8 || (n - 8) % 10 !== 0) return null;
          this.time = r.time = i64(0);
          for (let i = 8; i < n; i += 10) r.values.push({ member: u16(i), bits: view.getBigUint64(i + 2, true) });
          return r;
        case RecordType.overflow:
          if (n !== 8) return null;
          r.dropped = view.getBigUint64(0, true);
          return r;
        default:
          return null;
      }
    }

    /** The record as one line with the dictionary's names, as the C++ reader's describe(). */
    describe(r) {
      const d = this.dictionary;
      const line = `[${delayLabel(r.time)}] `;
      const target = (t) => (t === NONE ? 'internal' : d.stateName(t));
      switch (r.type) {
        case RecordType.hello:
          return `${line}chart ${d.chart}`;
        case RecordType.state:
          return `${line}state ${r.state} ${d.stateName(r.state)}`;
        case RecordType.event:
          return `${line}event ${r.event} ${d.eventName(r.event)}`;
        case RecordType.row: {
          const row = d.rows[r.row] ?? newRow();
          return `${line}row ${r.row} ${d.stateName(row.source)} -> ${target(row.target)}${row.label ? ` : ${row.label}` : ''}`;
        }
        case RecordType.member:
          return `${line}member ${r.member} ${d.memberName(r.member)}`;
        case RecordType.dispatch:
          return `${line}dispatch ${d.eventName(r.event)}`;
        case RecordType.cycle:
          return `${line}cycle`;
        case RecordType.cycleEnd:
          return `${line}cycle end`;
        case RecordType.exit:
          return `${line}exit ${d.stateName(r.state)}`;
        case RecordType.entry:
          return `${line}entry ${d.stateName(r.state)}`;
        case RecordType.transition: {
          let on;
          if (r.event === EVENTLESS) on = 'condition';
          else if (r.event === TIMEOUT) on = `after(${delayLabel(r.delay)})`;
          else on = d.eventName(r.event);
          return `${line}transition ${d.stateName(r.source)} -> ${target(r.target)} on ${on} (row ${r.row})`;
        }
        case RecordType.deferral:
          return `${line}defer ${d.eventName(r.event)} in ${d.stateName(r.state)}`;
        case RecordType.values:
          return `${line}values${r.values.map((v) => ` ${d.memberName(v.member)}=${d.valueText(v.member, v.bits)}`).join('')}`;
        case RecordType.configuration:
          return `${line}configuration${r.begins ? '' : ' (more)'}${r.active.map((n) => ` ${d.stateName(n)}`).join('')}`;
        case RecordType.overflow:
          return `${line}overflow: ${r.dropped} frames dropped`;
        default:
          return line;
      }
    }
  }

  /**
   * The active configuration and the members' values a run of records leaves: entries add a
   * state, exits remove it; the transitions of the latest step (since the last dispatch or cycle)
   * are kept to show which fired.
   *
   * A hello alone changes nothing: a tracer writes its dictionary again for readers that join
   * late, in the middle of a run, and then a configuration record, which sets the active states
   * outright (begins) or adds to them (more than one record's worth), so that a reader starting
   * there knows them too. A machine that starts enters its root (state 1) first, so that entry
   * starts the configuration afresh, and a hello naming another chart starts everything afresh.
   */
  class TraceState {
    constructor(from) {
      this.active = new Set(from ? from.active : []);
      this.values = new Map(from ? from.values : []);
      this.fired = from ? from.fired.slice() : [];
      this.chart = from ? from.chart : null;
    }
    clone() {
      return new TraceState(this);
    }
    apply(r) {
      switch (r.type) {
        case RecordType.hello:
          if (this.chart !== null && r.chart !== this.chart) {
            this.active.clear();
            this.values.clear();
            this.fired = [];
          }
          this.chart = r.chart ?? null;
          break;
        case RecordType.dispatch:
        case RecordType.cycle:
          this.fired = [];
          break;
        case RecordType.entry:
          if (r.state === ROOT) this.active.clear();
          this.active.add(r.state);
          break;
        case RecordType.exit:
          this.active.delete(r.state);
          break;
        case RecordType.configuration:
          if (r.begins) this.active.clear();
          for (const n of r.active) this.active.add(n);
          break;
        case RecordType.transition:
          this.fired.push(r.row);
          break;
        case RecordType.values:
          for (const v of r.values) this.values.set(v.member, v.bits);
          break;
        default:
          break;
      }
    }
  }

  const api = {
    RecordType,
    NONE,
    EVENTLESS,
    TIMEOUT,
    ROOT,
    StateKind,
    MemberKind,
    crc16,
    delayLabel,
    doubleText,
    TraceDictionary,
    TraceReader,
    TraceState,
  };
  globalThis.BscTrace = api;
  if (typeof module === 'object' && module && module.exports) module.exports = api;
})();
