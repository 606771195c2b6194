#pragma once
// Real numbers for .inp data lines. CalculiX reads at most 20 characters of a number and
// silently misreads a 21-character one, so every field is cut to 20: the shortest text that
// reads back to the same double when it fits, else the most digits that fit. Values below
// `zero_below` in magnitude - round-off on a plane that is exactly 0, 1e-26 beside a model of
// size 10 - are written as 0.
#include <charconv>
#include <cmath>
#include <cstddef>

namespace tubemesh::io {

inline constexpr std::size_t kAbaqusNumberWidth = 20;

// Writes into `text` (at least 32 characters) and returns the length, at most 20.
inline std::size_t abaqus_number(double value, double zero_below, char* text) {
    if (std::abs(value) < zero_below) value = 0;
    auto result = std::to_chars(text, text + 32, value);
    for (int precision = 17; static_cast<std::size_t>(result.ptr - text) > kAbaqusNumberWidth && precision > 1;
         --precision)
        result = std::to_chars(text, text + 32, value, std::chars_format::general, precision);
    return static_cast<std::size_t>(result.ptr - text);
}

}  // namespace tubemesh::io
