#pragma once
// A small command-line parser: positional arguments plus `--flag value` / `--switch`
// options, each declared up front so unknown flags are an error rather than ignored.
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace pt::cli {

// Bad usage: main prints "pt-render <command>: <message>" and exits 2.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class Options {
public:
    // `valued`: flags that take a value (aliases like "-o" allowed); `switches`: flags without.
    Options(const std::vector<std::string>& args, const std::set<std::string>& valued,
            const std::set<std::string>& switches);

    const std::vector<std::string>& positional() const { return positional_; }
    bool has(const std::string& flag) const { return values_.count(flag) || switches_.count(flag); }
    std::optional<std::string> value(const std::string& flag) const;
    std::optional<uint32_t> positiveInt(const std::string& flag) const;  // > 0
    std::optional<uint32_t> nonNegativeInt(const std::string& flag) const;
    std::optional<double> positiveNumber(const std::string& flag) const;
    // "WxH", both > 0.
    std::optional<std::pair<uint32_t, uint32_t>> size(const std::string& flag) const;

private:
    std::vector<std::string> positional_;
    std::map<std::string, std::string> values_;
    std::set<std::string> switches_;
};

}  // namespace pt::cli
