#pragma once
// Distributed systems (opt-in): a bsc::system's actors deployed on several nodes, linked over a
// publish/subscribe transport. This header has no dependency beyond the standard library; the
// MQTT transport is <bsc/mqtt.hpp> (CMake target bsc::mqtt, needs libmosquitto).

#include <bsc/net/memory_transport.hpp>
#include <bsc/net/node.hpp>
#include <bsc/net/transport.hpp>
#include <bsc/net/wire.hpp>
