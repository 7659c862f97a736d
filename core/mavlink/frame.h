// MAVLink frames on the wire: encoding MAVLink 2 frames and parsing a byte stream of MAVLink 1 and 2
// frames (checksum with each message's CRC extra byte; signed frames are accepted unsigned-checked).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace pf::mavlink {

using Bytes = std::vector<std::uint8_t>;

constexpr std::uint8_t kMagicV1 = 0xFE;
constexpr std::uint8_t kMagicV2 = 0xFD;
constexpr std::uint8_t kIncompatSigned = 0x01;

// One message as sent or received: who sent it and its payload (MAVLink 2 payloads arrive with their
// trailing zero bytes cut; decoders pad them back).
struct Frame {
    std::uint8_t version = 2;
    std::uint8_t seq = 0;
    std::uint8_t systemId = 0;
    std::uint8_t componentId = 0;
    std::uint32_t messageId = 0;
    Bytes payload;
};

// The CRC extra byte of a message id this library knows, else nullopt (such frames cannot be
// checked and are skipped by the parser).
std::optional<std::uint8_t> crcExtraFor(std::uint32_t messageId);

// A MAVLink 2 frame (no signature). Trailing zero bytes of the payload are cut as the protocol says,
// but one byte is always kept, as the reference implementation does.
Bytes encodeFrame(const Frame& frame);

// Turns a byte stream into frames. Garbage, frames with a bad checksum and frames of unknown
// messages are skipped (and counted); a frame split across reads is completed by the next feed().
class FrameParser {
public:
    std::vector<Frame> feed(const std::uint8_t* data, std::size_t n);
    std::vector<Frame> feed(const Bytes& bytes) { return feed(bytes.data(), bytes.size()); }

    std::size_t badChecksums() const { return m_badCrc; }
    std::size_t unknownMessages() const { return m_unknown; }

private:
    Bytes m_buf;
    std::size_t m_badCrc = 0;
    std::size_t m_unknown = 0;
};

} // namespace pf::mavlink
