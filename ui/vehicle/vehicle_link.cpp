#include "ui/vehicle/vehicle_link.h"

#include "ui/vehicle/serial_link.h"
#include "ui/vehicle/tcp_link.h"
#include "ui/vehicle/udp_link.h"

namespace pf::ui {

std::unique_ptr<VehicleLink> createLink(const mavlink::ConnectionSpec& spec) {
    switch (spec.kind) {
    case mavlink::ConnectionSpec::Kind::UdpClient:
    case mavlink::ConnectionSpec::Kind::UdpServer:
        return std::make_unique<UdpLink>(spec);
    case mavlink::ConnectionSpec::Kind::Tcp:
        return std::make_unique<TcpLink>(spec);
    case mavlink::ConnectionSpec::Kind::Serial:
        return std::make_unique<SerialLink>(spec);
    }
    return nullptr;
}

} // namespace pf::ui
