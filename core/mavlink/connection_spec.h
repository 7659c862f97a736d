// Where a vehicle is reached, as the user writes it: udp:HOST:PORT (Photoflight sends first),
// udp::PORT or udpin:PORT (Photoflight listens, the vehicle sends first), tcp:HOST:PORT,
// serial:DEVICE[:BAUD]. Parsed here so the CLI and the GUI accept the same text.
#pragma once

#include "core/result.h"

#include <string>

namespace pf::mavlink {

struct ConnectionSpec {
    enum class Kind { UdpClient, UdpServer, Tcp, Serial };
    Kind kind = Kind::UdpClient;
    std::string host; // UDP client and TCP; the address to listen on for a UDP server
    int port = 0;
    std::string device; // serial
    int baud = 57600;
    // The canonical text ("udp:127.0.0.1:14550", "udpin:0.0.0.0:14550", "serial:/dev/ttyUSB0:57600").
    std::string text() const;
    // In words for messages ("UDP 127.0.0.1:14550", "serial port /dev/ttyUSB0 at 57600 baud").
    std::string describe() const;
};

Result<ConnectionSpec> parseConnectionSpec(const std::string& text);

} // namespace pf::mavlink
