#include "engine/io/msh_cursor.hpp"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cstring>

#include "engine/core/types.hpp"

namespace tubemesh::io {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

// Short, printable excerpt of a bad token for messages (binary junk must not flood them).
std::string shown(std::string_view text) {
    std::string s(text.substr(0, 40));
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    return "\"" + s + (text.size() > 40 ? "...\"" : "\"");
}

}  // namespace

void MshCursor::fail(const std::string& message) const {
    const std::string place =
        binary_ ? "byte offset " + std::to_string(item_pos_) : "line " + std::to_string(item_line_);
    throw Error(name_ + ": " + place + ": " + message);
}

void MshCursor::skip_space() {
    while (pos_ < data_.size() && is_space(data_[pos_])) {
        if (data_[pos_] == '\n') ++line_;
        ++pos_;
    }
}

void MshCursor::start_item() {
    item_pos_ = pos_;
    item_line_ = line_;
}

bool MshCursor::at_end() {
    skip_space();
    return pos_ == data_.size();
}

std::string_view MshCursor::token(std::string_view what) {
    skip_space();
    start_item();
    if (pos_ == data_.size()) fail("expected " + std::string(what) + ", found the end of the file");
    const std::size_t begin = pos_;
    while (pos_ < data_.size() && !is_space(data_[pos_])) ++pos_;
    return data_.substr(begin, pos_ - begin);
}

void MshCursor::expect(std::string_view word) {
    const std::string_view t = token(word);
    if (t != word) fail("expected " + std::string(word) + ", found " + shown(t));
}

void MshCursor::end_of_line() {
    while (pos_ < data_.size() && (data_[pos_] == ' ' || data_[pos_] == '\t' || data_[pos_] == '\r')) ++pos_;
    start_item();
    if (pos_ == data_.size() || data_[pos_] != '\n') fail("expected the end of the line");
    ++pos_;
    ++line_;
}

std::string MshCursor::quoted(std::string_view what) {
    skip_space();
    start_item();
    if (pos_ == data_.size() || data_[pos_] != '"') fail("expected " + std::string(what) + " in double quotes");
    const std::size_t close = data_.find_first_of("\"\n", pos_ + 1);
    if (close == std::string_view::npos || data_[close] != '"')
        fail(std::string(what) + " has no closing double quote on its line");
    std::string text(data_.substr(pos_ + 1, close - pos_ - 1));
    pos_ = close + 1;
    return text;
}

void MshCursor::skip_section(std::string_view name) {
    const std::string end = "$End" + std::string(name);
    const std::size_t found = data_.find(end, pos_);
    if (found == std::string_view::npos) fail("section $" + std::string(name) + " has no " + end);
    const std::size_t after = found + end.size();
    line_ += static_cast<std::size_t>(std::count(data_.begin() + static_cast<std::ptrdiff_t>(pos_),
                                                 data_.begin() + static_cast<std::ptrdiff_t>(after), '\n'));
    pos_ = after;
}

std::int64_t MshCursor::parse_integer(std::string_view text, std::string_view what) {
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size())
        fail("expected " + std::string(what) + " (an integer), found " + shown(text));
    return v;
}

std::uint64_t MshCursor::text_size(std::string_view what) {
    const std::int64_t v = parse_integer(token(what), what);
    if (v < 0) fail(std::string(what) + " is negative (" + std::to_string(v) + ")");
    return static_cast<std::uint64_t>(v);
}

int MshCursor::text_int(std::string_view what) {
    const std::int64_t v = parse_integer(token(what), what);
    if (v < INT_MIN || v > INT_MAX) fail(std::string(what) + " " + std::to_string(v) + " is out of range");
    return static_cast<int>(v);
}

template <class T>
T MshCursor::raw(std::string_view what) {
    start_item();
    if (data_.size() - pos_ < sizeof(T))
        fail("the file ends inside " + std::string(what) + " (" + std::to_string(sizeof(T)) + " bytes needed, " +
             std::to_string(data_.size() - pos_) + " left)");
    T v;
    std::memcpy(&v, data_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
}

std::uint64_t MshCursor::size_value(std::string_view what) {
    if (!binary_) return text_size(what);
    return size_width_ == 8 ? raw<std::uint64_t>(what) : raw<std::uint32_t>(what);
}

int MshCursor::int_value(std::string_view what) {
    if (!binary_) return text_int(what);
    return raw<std::int32_t>(what);
}

double MshCursor::double_value(std::string_view what) {
    if (!binary_) {
        const std::string_view text = token(what);
        double v = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec != std::errc() || end != text.data() + text.size())
            fail("expected " + std::string(what) + " (a number), found " + shown(text));
        return v;
    }
    return raw<double>(what);
}

void MshCursor::check_count(std::uint64_t count, std::size_t binary_bytes_each, std::string_view what) {
    const std::size_t left = data_.size() - pos_;
    const std::uint64_t fits = binary_ ? left / std::max<std::size_t>(binary_bytes_each, 1) : (left + 1) / 2;
    if (count > fits)
        fail(std::string(what) + " count " + std::to_string(count) +
             " is more than the rest of the file can hold (the file is truncated or corrupt)");
}

}  // namespace tubemesh::io
