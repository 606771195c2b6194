#pragma once
// Reading position in a Gmsh file held in memory.
//
// MSH 4.1 mixes text (section markers, $MeshFormat, $PhysicalNames) with values that are text
// in ASCII files and raw little-endian bytes in binary ones; the value readers pick the right
// form. Every read is bounds-checked, and every error names the file and the place of the
// item being read: "line N" in ASCII files, "byte offset N" in binary ones.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

namespace tubemesh::io {

class MshCursor {
public:
    MshCursor(std::string_view data, std::string file_name) : data_(data), name_(std::move(file_name)) {}

    // After $MeshFormat: values are raw bytes from now on, "size_t" values `size_width` wide.
    void use_binary(int size_width) {
        binary_ = true;
        size_width_ = size_width;
    }
    bool binary() const { return binary_; }

    // Text, in both encodings.
    bool at_end();                                    // true when only white space is left
    std::string_view token(std::string_view what);    // next white-space separated word
    void expect(std::string_view word);               // the next token must be `word`
    void end_of_line();                               // rest of the line must be blank
    std::string quoted(std::string_view what);        // "text" on one line
    void skip_section(std::string_view name);         // past "$End<name>"
    std::uint64_t text_size(std::string_view what);
    int text_int(std::string_view what);

    // Values: text in ASCII files, raw bytes in binary ones (MSH types size_t, int, double).
    std::uint64_t size_value(std::string_view what);
    int int_value(std::string_view what);
    double double_value(std::string_view what);

    // Fails unless the rest of the file can hold `count` items: `binary_bytes_each` bytes each
    // in binary files, two characters each in ASCII ones. Call it before sizing anything by a
    // count read from the file, so a corrupt count is an error and not a huge allocation.
    void check_count(std::uint64_t count, std::size_t binary_bytes_each, std::string_view what);

    // Throws tubemesh::Error "<file>: <place>: <message>" for the item read last.
    [[noreturn]] void fail(const std::string& message) const;

private:
    void skip_space();
    void start_item();
    std::int64_t parse_integer(std::string_view text, std::string_view what);
    template <class T>
    T raw(std::string_view what);

    std::string_view data_;
    std::string name_;
    std::size_t pos_ = 0;
    std::size_t line_ = 1;       // line of pos_ (ASCII files)
    std::size_t item_pos_ = 0;   // start of the item read last, for messages
    std::size_t item_line_ = 1;
    bool binary_ = false;
    int size_width_ = 8;
};

}  // namespace tubemesh::io
