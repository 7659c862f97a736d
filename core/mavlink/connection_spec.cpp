#include "core/mavlink/connection_spec.h"

#include <cctype>

namespace pf::mavlink {

namespace {

Error bad(const std::string& text, const std::string& why) {
    return makeError(ErrorCode::InvalidInput,
                     "connection \"" + text + "\": " + why +
                         " (use udp:HOST:PORT, udpin:PORT, tcp:HOST:PORT or serial:DEVICE:BAUD)");
}

bool parseInt(const std::string& s, int lo, int hi, int& out) {
    if (s.empty() || s.size() > 9)
        return false;
    for (char c : s)
        if (!std::isdigit(static_cast<unsigned char>(c)))
            return false;
    out = std::stoi(s);
    return out >= lo && out <= hi;
}

} // namespace

std::string ConnectionSpec::text() const {
    switch (kind) {
    case Kind::UdpClient:
        return "udp:" + host + ":" + std::to_string(port);
    case Kind::UdpServer:
        return "udpin:" + host + ":" + std::to_string(port);
    case Kind::Tcp:
        return "tcp:" + host + ":" + std::to_string(port);
    case Kind::Serial:
        return "serial:" + device + ":" + std::to_string(baud);
    }
    return {};
}

std::string ConnectionSpec::describe() const {
    switch (kind) {
    case Kind::UdpClient:
        return "UDP " + host + ":" + std::to_string(port);
    case Kind::UdpServer:
        return "UDP port " + std::to_string(port) + " (listening)";
    case Kind::Tcp:
        return "TCP " + host + ":" + std::to_string(port);
    case Kind::Serial:
        return "serial port " + device + " at " + std::to_string(baud) + " baud";
    }
    return {};
}

Result<ConnectionSpec> parseConnectionSpec(const std::string& text) {
    const auto colon = text.find(':');
    if (colon == std::string::npos)
        return bad(text, "no transport given");
    std::string scheme = text.substr(0, colon);
    for (char& c : scheme)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const std::string rest = text.substr(colon + 1);
    ConnectionSpec s;
    if (scheme == "serial") {
        const auto last = rest.rfind(':');
        s.kind = ConnectionSpec::Kind::Serial;
        s.device = rest;
        if (last != std::string::npos) {
            int baud = 0;
            if (!parseInt(rest.substr(last + 1), 50, 4000000, baud))
                return bad(text, "the baud rate \"" + rest.substr(last + 1) + "\" is not a number from 50 to 4000000");
            s.device = rest.substr(0, last);
            s.baud = baud;
        }
        if (s.device.empty())
            return bad(text, "no serial device given");
        return s;
    }
    if (scheme != "udp" && scheme != "udpin" && scheme != "udpout" && scheme != "tcp")
        return bad(text, "unknown transport \"" + scheme + "\"");
    const auto last = rest.rfind(':');
    const std::string host = last == std::string::npos ? std::string() : rest.substr(0, last);
    const std::string portText = last == std::string::npos ? rest : rest.substr(last + 1);
    if (!parseInt(portText, 1, 65535, s.port))
        return bad(text, portText.empty() ? "no port given"
                                          : "the port \"" + portText + "\" is not a number from 1 to 65535");
    s.host = host;
    if (scheme == "tcp") {
        s.kind = ConnectionSpec::Kind::Tcp;
        if (host.empty())
            return bad(text, "no host given");
    } else if (scheme == "udpin" || (scheme == "udp" && (host.empty() || host == "0.0.0.0"))) {
        s.kind = ConnectionSpec::Kind::UdpServer;
        if (s.host.empty())
            s.host = "0.0.0.0";
    } else {
        s.kind = ConnectionSpec::Kind::UdpClient;
        if (host.empty())
            return bad(text, "no host given");
    }
    return s;
}

} // namespace pf::mavlink
