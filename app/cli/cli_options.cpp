#include "cli/cli_options.h"

#include <cmath>
#include <cstdlib>

namespace pt::cli {

Options::Options(const std::vector<std::string>& args, const std::set<std::string>& valued,
                 const std::set<std::string>& switches) {
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a.size() > 1 && a[0] == '-') {
            if (switches.count(a)) {
                switches_.insert(a);
            } else if (valued.count(a)) {
                if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
                values_[a] = args[++i];
            } else {
                throw UsageError("unknown option " + a);
            }
        } else {
            positional_.push_back(a);
        }
    }
}

std::optional<std::string> Options::value(const std::string& flag) const {
    auto it = values_.find(flag);
    if (it == values_.end()) return std::nullopt;
    return it->second;
}

std::optional<uint32_t> Options::nonNegativeInt(const std::string& flag) const {
    auto v = value(flag);
    if (!v) return std::nullopt;
    char* end = nullptr;
    const long long n = std::strtoll(v->c_str(), &end, 10);
    if (v->empty() || *end != '\0' || n < 0 || n > 0xffffffffLL) {
        throw UsageError(flag + ": expected a whole number, got \"" + *v + "\"");
    }
    return uint32_t(n);
}

std::optional<uint32_t> Options::positiveInt(const std::string& flag) const {
    auto n = nonNegativeInt(flag);
    if (n && *n == 0) throw UsageError(flag + ": must be at least 1");
    return n;
}

std::optional<double> Options::positiveNumber(const std::string& flag) const {
    auto v = value(flag);
    if (!v) return std::nullopt;
    char* end = nullptr;
    const double x = std::strtod(v->c_str(), &end);
    if (v->empty() || *end != '\0' || !std::isfinite(x) || x <= 0.0) {
        throw UsageError(flag + ": expected a positive number, got \"" + *v + "\"");
    }
    return x;
}

std::optional<std::pair<uint32_t, uint32_t>> Options::size(const std::string& flag) const {
    auto v = value(flag);
    if (!v) return std::nullopt;
    const size_t x = v->find('x');
    char* end = nullptr;
    if (x != std::string::npos) {
        const long w = std::strtol(v->substr(0, x).c_str(), &end, 10);
        const bool wOk = *end == '\0';
        const long h = std::strtol(v->substr(x + 1).c_str(), &end, 10);
        if (wOk && *end == '\0' && w > 0 && h > 0 && w <= 32768 && h <= 32768 && x > 0) {
            return std::make_pair(uint32_t(w), uint32_t(h));
        }
    }
    throw UsageError(flag + ": expected WIDTHxHEIGHT (1 to 32768 each), got \"" + *v + "\"");
}

}  // namespace pt::cli
