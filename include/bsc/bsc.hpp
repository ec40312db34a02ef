#pragma once
// bsc: Basic Statecharts for C++20. Include this header to get the whole library.

#include <bsc/allow.hpp>
#include <bsc/chart.hpp>
#include <bsc/chart_ref.hpp>
#include <bsc/configuration.hpp>
#include <bsc/data/channel.hpp>
#include <bsc/data/timer.hpp>
#include <bsc/dsl/action.hpp>
#include <bsc/dsl/delayed.hpp>
#include <bsc/dsl/guard.hpp>
#include <bsc/dsl/named.hpp>
#include <bsc/dsl/row.hpp>
#include <bsc/dsl/state.hpp>
#include <bsc/dsl/tree.hpp>
#include <bsc/duration.hpp>
#include <bsc/error.hpp>
#include <bsc/events.hpp>
#include <bsc/fields.hpp>
#include <bsc/machine.hpp>
#include <bsc/observer.hpp>
#include <bsc/outcome.hpp>
#include <bsc/policies.hpp>
#include <bsc/system.hpp>
#include <bsc/table/machine.hpp>
#include <bsc/transient.hpp>
#include <bsc/version.hpp>
