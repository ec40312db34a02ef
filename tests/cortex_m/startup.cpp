// The start of a Cortex-M4 program on QEMU's mps2-an386 (tests/cortex_m/): the vector table,
// the reset handler that prepares memory as C++ expects it (.data copied from flash, .bss
// zeroed, the constructors of .init_array run), the command line from semihosting as main's
// argv, and the exit code back to QEMU through semihosting. A fault or abort() stops QEMU with
// a failing exit code instead of hanging it.

#include <cstdint>

#include "console.hpp"

extern "C" {
// Defined by mps2_an386.ld.
extern std::uint32_t __data_load[], __data_start[], __data_end[], __bss_start[], __bss_end[];
extern std::uint32_t __stack_top[];
extern void (*__init_array_start[])();
extern void (*__init_array_end[])();

// C++ forbids calling main; the startup reaches it through its symbol.
int program_main(int argc, char** argv) asm("main");
[[noreturn]] void reset_handler();
[[noreturn]] void fault_handler();
[[noreturn]] void abort();
}

namespace {

[[noreturn]] void stop(int code) {
    // ADP_Stopped_ApplicationExit with the exit code as its subcode.
    std::uint32_t const block[2] = {0x20026, static_cast<std::uint32_t>(code)};
    cm::semihosting::call(cm::semihosting::sys_exit_extended, block);
    for (;;) {
    }
}

// main's arguments: QEMU passes each `arg=` of -semihosting-config (without any, the kernel's
// path and -append's text), separated by spaces.
constexpr int max_args = 8;
char command_line[160];
char* arguments[max_args + 1];

int split_command_line() {
    struct {
        char* buffer;
        int length;
    } block{command_line, sizeof command_line - 1};
    if (cm::semihosting::call(cm::semihosting::sys_get_cmdline, &block) != 0) return 0;
    command_line[block.length] = '\0';
    int argc = 0;
    for (char* p = command_line; *p != '\0' && argc < max_args;) {
        while (*p == ' ') *p++ = '\0';
        if (*p == '\0') break;
        arguments[argc++] = p;
        while (*p != '\0' && *p != ' ') ++p;
    }
    arguments[argc] = nullptr;
    return argc;
}

}  // namespace

void reset_handler() {
    for (std::uint32_t *from = __data_load, *to = __data_start; to < __data_end;) *to++ = *from++;
    for (std::uint32_t* to = __bss_start; to < __bss_end;) *to++ = 0;
    for (auto** f = __init_array_start; f < __init_array_end; ++f) (*f)();
    int const argc = split_command_line();
    stop(program_main(argc, arguments));
}

void fault_handler() {
    cm::write("fault\n");
    stop(70);
}

void abort() {
    cm::write("abort\n");
    stop(134);
}

// The core's exceptions: the initial stack pointer, reset, and 14 system handlers (NMI,
// HardFault, MemManage, BusFault, UsageFault, four reserved, SVCall, DebugMonitor, reserved,
// PendSV, SysTick). No peripheral interrupt is enabled, so the table stops there.
[[gnu::section(".vectors"), gnu::used]] void const* const vector_table[16] = {
    __stack_top,
    reinterpret_cast<void const*>(&reset_handler),
    reinterpret_cast<void const*>(&fault_handler),
    reinterpret_cast<void const*>(&fault_handler),
    reinterpret_cast<void const*>(&fault_handler),
    reinterpret_cast<void const*>(&fault_handler),
    reinterpret_cast<void const*>(&fault_handler),
    nullptr,
    nullptr,
    nullptr,
    nullptr,
    reinterpret_cast<void const*>(&fault_handler),
    reinterpret_cast<void const*>(&fault_handler),
    nullptr,
    reinterpret_cast<void const*>(&fault_handler),
    reinterpret_cast<void const*>(&fault_handler)};
