#pragma once
// Option validators that reject at parse time with the allowed values in plain numbers
// ("--layers must be a whole number from 1 to 8, got 64"), NaN and infinity included.
#include <CLI/CLI.hpp>

namespace tubemesh::cli {

// A whole number from `lo` to `hi`.
CLI::Validator whole_number(long long lo, long long hi);

// A finite number from `lo` to `hi`.
CLI::Validator number_between(double lo, double hi);

// A finite number above 0.
CLI::Validator positive_number();

}  // namespace tubemesh::cli
