// Uses the installed bsc::mqtt: a transport to a port where no broker listens stays unconnected
// and says so, without blocking longer than asked.
#include <bsc/mqtt.hpp>

#include <chrono>

int main() {
    bsc::net::mosquitto_transport transport{
        bsc::net::mqtt_endpoint{"127.0.0.1", 1, "consumer", 5, std::chrono::milliseconds{10}}};
    transport.subscribe("bsc/#");
    auto const delivered = transport.poll(std::chrono::milliseconds{50}, [](bsc::net::message const&) {});
    return delivered == 0 && !transport.connected() ? 0 : 1;
}
