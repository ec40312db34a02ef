// The reference of the header probe (header_bsc.cpp): the same small program without bsc.

#include "small_driver.hpp"

int main() {
    int counted = 0;
    probe_driver::time_loop([&] {
        for (int i = 0; i < 1'000'000; ++i) counted += i & 1;
    });
    probe_driver::print_size(counted);
}
