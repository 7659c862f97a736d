#include "core/mavlink/frame.h"

#include "core/mavlink/crc.h"

#include <algorithm>

namespace pf::mavlink {

Bytes encodeFrame(const Frame& f) {
    std::size_t len = f.payload.size();
    while (len > 1 && f.payload[len - 1] == 0)
        --len;
    len = std::min<std::size_t>(len, 255);
    Bytes payload(f.payload.begin(), f.payload.begin() + static_cast<long>(len));
    if (payload.empty())
        payload.push_back(0);
    Bytes out;
    out.reserve(len + 12);
    out.push_back(kMagicV2);
    out.push_back(static_cast<std::uint8_t>(payload.size()));
    out.push_back(0); // incompat flags: not signed
    out.push_back(0); // compat flags
    out.push_back(f.seq);
    out.push_back(f.systemId);
    out.push_back(f.componentId);
    out.push_back(static_cast<std::uint8_t>(f.messageId & 0xFF));
    out.push_back(static_cast<std::uint8_t>((f.messageId >> 8) & 0xFF));
    out.push_back(static_cast<std::uint8_t>((f.messageId >> 16) & 0xFF));
    out.insert(out.end(), payload.begin(), payload.end());
    X25Crc crc;
    crc.add(out.data() + 1, out.size() - 1);
    crc.add(crcExtraFor(f.messageId).value_or(0));
    out.push_back(static_cast<std::uint8_t>(crc.value() & 0xFF));
    out.push_back(static_cast<std::uint8_t>(crc.value() >> 8));
    return out;
}

std::vector<Frame> FrameParser::feed(const std::uint8_t* data, std::size_t n) {
    m_buf.insert(m_buf.end(), data, data + n);
    std::vector<Frame> frames;
    std::size_t pos = 0;
    while (pos < m_buf.size()) {
        const std::uint8_t magic = m_buf[pos];
        if (magic != kMagicV1 && magic != kMagicV2) {
            ++pos;
            continue;
        }
        const bool v2 = magic == kMagicV2;
        const std::size_t header = v2 ? 10 : 6;
        if (m_buf.size() - pos < header)
            break; // wait for the rest of the header
        const std::size_t len = m_buf[pos + 1];
        const bool signedFrame = v2 && (m_buf[pos + 2] & kIncompatSigned);
        const std::size_t total = header + len + 2 + (signedFrame ? 13 : 0);
        if (m_buf.size() - pos < total)
            break;
        Frame f;
        f.version = v2 ? 2 : 1;
        if (v2) {
            f.seq = m_buf[pos + 4];
            f.systemId = m_buf[pos + 5];
            f.componentId = m_buf[pos + 6];
            f.messageId = static_cast<std::uint32_t>(m_buf[pos + 7]) |
                          (static_cast<std::uint32_t>(m_buf[pos + 8]) << 8) |
                          (static_cast<std::uint32_t>(m_buf[pos + 9]) << 16);
        } else {
            f.seq = m_buf[pos + 2];
            f.systemId = m_buf[pos + 3];
            f.componentId = m_buf[pos + 4];
            f.messageId = m_buf[pos + 5];
        }
        const auto extra = crcExtraFor(f.messageId);
        if (!extra) {
            // Cannot be checked: a message we do not use, or a false start inside other bytes.
            // Moving on by one byte never swallows a real frame that follows.
            ++m_unknown;
            ++pos;
            continue;
        }
        X25Crc crc;
        crc.add(m_buf.data() + pos + 1, header - 1 + len);
        crc.add(*extra);
        const std::uint16_t got = static_cast<std::uint16_t>(m_buf[pos + header + len] |
                                                             (m_buf[pos + header + len + 1] << 8));
        if (got != crc.value()) {
            ++m_badCrc;
            ++pos; // a false start byte inside other data: look for the next one
            continue;
        }
        f.payload.assign(m_buf.begin() + static_cast<long>(pos + header),
                         m_buf.begin() + static_cast<long>(pos + header + len));
        frames.push_back(std::move(f));
        pos += total;
    }
    m_buf.erase(m_buf.begin(), m_buf.begin() + static_cast<long>(pos));
    return frames;
}

} // namespace pf::mavlink
