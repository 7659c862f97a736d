// Result<T>: a value or an Error that names the input and what is wrong, for every core API.
#pragma once

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace pf {

enum class ErrorCode {
    InvalidInput,    // a parameter out of range (altitude <= 0, overlap >= 1, ...)
    InvalidGeometry, // polygon problems: too few vertices, self-intersection, zero area, ...
    TooLarge,        // the problem would exceed a configured budget (cells, memory)
    ParseError,      // a file or string could not be understood
    IoError,         // a file could not be read or written
    NotFound,        // a named item (camera, aircraft, field) does not exist
    NoPath,          // no safe path exists between two places
    Unsupported,     // a format, version or option this build does not handle
    Cancelled,       // the caller asked to stop
    Internal,        // a bug: should never reach a user
};

struct Error {
    ErrorCode code = ErrorCode::Internal;
    std::string message;
};

inline Error makeError(ErrorCode code, std::string message) { return Error{code, std::move(message)}; }

template <class T> class [[nodiscard]] Result {
public:
    Result(T value) : m_v(std::move(value)) {}
    Result(Error error) : m_v(std::move(error)) {}

    bool ok() const { return m_v.index() == 0; }
    explicit operator bool() const { return ok(); }

    const T& value() const& { assert(ok()); return std::get<0>(m_v); }
    T& value() & { assert(ok()); return std::get<0>(m_v); }
    T&& value() && { assert(ok()); return std::get<0>(std::move(m_v)); }
    const T* operator->() const { return &value(); }
    T* operator->() { return &value(); }
    const T& operator*() const& { return value(); }
    T& operator*() & { return value(); }

    const Error& error() const { assert(!ok()); return std::get<1>(m_v); }

private:
    std::variant<T, Error> m_v;
};

template <> class [[nodiscard]] Result<void> {
public:
    Result() = default;
    Result(Error error) : m_error(std::move(error)), m_ok(false) {}
    bool ok() const { return m_ok; }
    explicit operator bool() const { return m_ok; }
    const Error& error() const { assert(!m_ok); return m_error; }

private:
    Error m_error;
    bool m_ok = true;
};

using Status = Result<void>;

} // namespace pf
