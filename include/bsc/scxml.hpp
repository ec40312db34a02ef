#pragma once
// What a chart compiled from an SCXML document by bsc-scxml needs (docs/scxml.md): bsc's DSL,
// the C++ datamodel's dynamic value, the event base, the session, the executable-content block
// and the policy.

#include <bsc/bsc.hpp>
#include <bsc/scxml/block.hpp>
#include <bsc/scxml/event.hpp>
#include <bsc/scxml/execution_error.hpp>
#include <bsc/scxml/policy.hpp>
#include <bsc/scxml/rows.hpp>
#include <bsc/scxml/session.hpp>
#include <bsc/scxml/value.hpp>
