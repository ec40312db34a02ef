#pragma once
// bsc::verify: exhaustive exploration of closed models of bsc machines, and the properties
// checked on it. Not included by <bsc/bsc.hpp>: it uses the heap and the standard library's
// strings and vectors, which the machines themselves never need.

#include <bsc/detail/verify/codec.hpp>
#include <bsc/verify/coverage.hpp>
#include <bsc/verify/explorer.hpp>
#include <bsc/verify/models.hpp>
#include <bsc/verify/properties.hpp>
