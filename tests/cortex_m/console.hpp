#pragma once
// Where the programs of tests/cortex_m/ write their trace: standard output on the host; on the
// Cortex-M4 (BSC_CORTEX_M_TARGET), the debugger's console through semihosting, which QEMU
// implements. The programs write through this header only, and never through printf, so that
// the target image holds no formatted output, no allocation and no file system.

#if defined(BSC_CORTEX_M_TARGET)

namespace cm::semihosting {

// The operations of Arm's semihosting specification used here.
enum operation : int {
    sys_write0 = 0x04,         // write a NUL-terminated string to the console
    sys_get_cmdline = 0x15,    // the command line (QEMU: the kernel's name and -semihosting-config arg=)
    sys_exit_extended = 0x20,  // stop, with an exit code (the 32-bit SYS_EXIT has none)
};

// On M-profile cores a semihosting call is BKPT 0xAB, with the operation in r0 and its
// argument in r1; the result comes back in r0.
inline int call(int op, void const* argument) {
    register int r0 asm("r0") = op;
    register void const* r1 asm("r1") = argument;
    asm volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

}  // namespace cm::semihosting

namespace cm {
inline void write(char const* text) { semihosting::call(semihosting::sys_write0, text); }
}  // namespace cm

#else

#include <cstdio>

namespace cm {
inline void write(char const* text) { std::fputs(text, stdout); }
}  // namespace cm

#endif
