# CMake toolchain file: bare-metal Cortex-M4 with Debian's arm-none-eabi GCC and newlib
# (gcc-arm-none-eabi, libstdc++-arm-none-eabi-newlib, libnewlib-arm-none-eabi). Soft float: the
# programs use no floating point, and the startup then need not enable the FPU.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(BSC_ARM_PREFIX "arm-none-eabi-" CACHE STRING "The prefix of the cross tools' names")
set(CMAKE_CXX_COMPILER ${BSC_ARM_PREFIX}g++)
set(CMAKE_CXX_FLAGS_INIT "-mcpu=cortex-m4 -mthumb -mfloat-abi=soft")

# A test program cannot link without a startup and a linker script: CMake's compiler checks
# build a static library instead.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
