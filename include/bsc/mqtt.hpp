#pragma once
// Distributed systems over MQTT: <bsc/net.hpp> and bsc::net::mosquitto_transport. Link with the
// CMake target bsc::mqtt (Eclipse Mosquitto's client library, Debian package libmosquitto-dev).

#include <bsc/net.hpp>
#include <bsc/net/mosquitto_transport.hpp>
