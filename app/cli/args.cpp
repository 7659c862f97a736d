#include "app/cli/args.h"

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace pf::cli {

Result<Args> Args::parse(const std::vector<std::string>& argv, const std::vector<OptionSpec>& specs) {
    Args out;
    auto find = [&](const std::string& name) -> const OptionSpec* {
        for (const auto& s : specs)
            if (s.name == name)
                return &s;
        return nullptr;
    };
    for (std::size_t i = 0; i < argv.size(); ++i) {
        const std::string& a = argv[i];
        if (a.size() < 3 || a.compare(0, 2, "--") != 0) {
            out.m_positionals.push_back(a);
            continue;
        }
        std::string name = a.substr(2);
        std::optional<std::string> inlineValue;
        if (auto eq = name.find('='); eq != std::string::npos) {
            inlineValue = name.substr(eq + 1);
            name = name.substr(0, eq);
        }
        const OptionSpec* spec = find(name);
        if (!spec)
            return makeError(ErrorCode::InvalidInput, "unknown option --" + name + " (see --help)");
        if (!spec->repeatable && out.m_values.count(name))
            return makeError(ErrorCode::InvalidInput, "option --" + name + " given more than once");
        if (!spec->takesValue) {
            if (inlineValue)
                return makeError(ErrorCode::InvalidInput, "option --" + name + " takes no value");
            out.m_values[name].push_back("");
            continue;
        }
        if (inlineValue) {
            out.m_values[name].push_back(*inlineValue);
        } else if (i + 1 < argv.size()) {
            out.m_values[name].push_back(argv[++i]);
        } else {
            return makeError(ErrorCode::InvalidInput, "option --" + name + " needs a value");
        }
    }
    return out;
}

std::optional<std::string> Args::value(const std::string& name) const {
    auto it = m_values.find(name);
    if (it == m_values.end() || it->second.empty())
        return std::nullopt;
    return it->second.back();
}

std::vector<std::string> Args::values(const std::string& name) const {
    auto it = m_values.find(name);
    return it == m_values.end() ? std::vector<std::string>{} : it->second;
}

namespace {

std::optional<double> toNumber(const std::string& s) {
    if (s.empty())
        return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

} // namespace

Result<std::optional<double>> Args::number(const std::string& name) const {
    auto v = value(name);
    if (!v)
        return std::optional<double>{};
    auto n = toNumber(*v);
    if (!n)
        return makeError(ErrorCode::InvalidInput, "option --" + name + ": '" + *v + "' is not a number");
    return std::optional<double>{*n};
}

int reportError(const Error& error) {
    return reportError(error.message, error.code == ErrorCode::Internal ? kExitInternal : kExitBadInput);
}

int reportError(const std::string& message, int exitCode) {
    std::cerr << "photoflight-cli: error: " << message << '\n';
    return exitCode;
}

Result<std::pair<double, double>> parseLonLat(const std::string& text, const std::string& option) {
    const auto comma = text.find(',');
    if (comma == std::string::npos)
        return makeError(ErrorCode::InvalidInput, option + ": expected LON,LAT but got '" + text + "'");
    auto lon = toNumber(text.substr(0, comma));
    auto lat = toNumber(text.substr(comma + 1));
    if (!lon || !lat)
        return makeError(ErrorCode::InvalidInput, option + ": '" + text + "' is not a LON,LAT pair of numbers");
    if (std::abs(*lon) > 180.0 || std::abs(*lat) > 90.0)
        return makeError(ErrorCode::InvalidInput,
                         option + ": '" + text + "' is out of range (longitude within ±180, latitude within ±90)");
    return std::make_pair(*lon, *lat);
}

} // namespace pf::cli
