// The MAVLink checksum: CRC-16/MCRF4XX ("X.25" in the MAVLink documents), seeded 0xFFFF.
#pragma once

#include <cstddef>
#include <cstdint>

namespace pf::mavlink {

class X25Crc {
public:
    void add(std::uint8_t byte) {
        std::uint8_t tmp = byte ^ static_cast<std::uint8_t>(m_crc & 0xFF);
        tmp = static_cast<std::uint8_t>(tmp ^ (tmp << 4));
        m_crc = static_cast<std::uint16_t>((m_crc >> 8) ^ (tmp << 8) ^ (tmp << 3) ^ (tmp >> 4));
    }
    void add(const std::uint8_t* data, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i)
            add(data[i]);
    }
    std::uint16_t value() const { return m_crc; }

private:
    std::uint16_t m_crc = 0xFFFF;
};

} // namespace pf::mavlink
