#pragma once
// The version of bsc. CMakeLists.txt reads its project version from these three lines, so that
// the header, the CMake package (bscConfigVersion.cmake) and the CHANGELOG name one version.

#define BSC_VERSION_MAJOR 0
#define BSC_VERSION_MINOR 2
#define BSC_VERSION_PATCH 0

/// The version as one number, major * 10000 + minor * 100 + patch (as fmt's FMT_VERSION), for
/// `#if BSC_VERSION >= 200`.
#define BSC_VERSION (BSC_VERSION_MAJOR * 10000 + BSC_VERSION_MINOR * 100 + BSC_VERSION_PATCH)
