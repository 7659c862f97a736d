// A small command-line argument reader for photoflight-cli: positionals, --name VALUE, --name=VALUE,
// repeated options and switches, with errors that name the offending argument.
#pragma once

#include "core/result.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace pf::cli {

struct OptionSpec {
    std::string name;     // without the leading dashes
    bool takesValue = true;
    bool repeatable = false;
};

class Args {
public:
    // Parses argv (after the command name). Unknown options and missing values are errors.
    static Result<Args> parse(const std::vector<std::string>& argv, const std::vector<OptionSpec>& specs);

    const std::vector<std::string>& positionals() const { return m_positionals; }
    bool has(const std::string& name) const { return m_values.count(name) > 0; }
    std::optional<std::string> value(const std::string& name) const;
    std::vector<std::string> values(const std::string& name) const;
    // A numeric option: an error names the option when the value is not a finite number.
    Result<std::optional<double>> number(const std::string& name) const;

private:
    std::vector<std::string> m_positionals;
    std::map<std::string, std::vector<std::string>> m_values;
};

// Exit codes shared by every command.
constexpr int kExitOk = 0;
constexpr int kExitInternal = 1;
constexpr int kExitBadInput = 2;

// Prints "photoflight-cli: error: MESSAGE" on stderr and returns the exit code for the error
// (Internal -> 1, anything the user can fix -> 2).
int reportError(const Error& error);
int reportError(const std::string& message, int exitCode = kExitBadInput);

// Parses a "LON,LAT" pair.
Result<std::pair<double, double>> parseLonLat(const std::string& text, const std::string& option);

} // namespace pf::cli
