#include "tools/cli/option_checks.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace tubemesh::cli {

namespace {

// The whole text as a number, or NaN when it is not one.
double parse_number(const std::string& text) {
    if (text.empty()) return NAN;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() ? value : NAN;
}

}  // namespace

CLI::Validator whole_number(long long lo, long long hi) {
    const std::string range = fmt::format("a whole number from {} to {}", lo, hi);
    return CLI::Validator(
        [lo, hi, range](std::string& text) -> std::string {
            long long value = 0;
            const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (error != std::errc() || end != text.data() + text.size() || value < lo || value > hi)
                return fmt::format("must be {}, got {}", range, text);
            return {};
        },
        fmt::format("INT in {}..{}", lo, hi));
}

CLI::Validator number_between(double lo, double hi) {
    return CLI::Validator(
        [lo, hi](std::string& text) -> std::string {
            const double value = parse_number(text);
            if (!(value >= lo && value <= hi)) return fmt::format("must be a number from {} to {}, got {}", lo, hi, text);
            return {};
        },
        fmt::format("NUMBER in {}..{}", lo, hi));
}

CLI::Validator positive_number() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            const double value = parse_number(text);
            if (!(value > 0 && std::isfinite(value))) return fmt::format("must be a positive number, got {}", text);
            return {};
        },
        "POSITIVE");
}

}  // namespace tubemesh::cli
