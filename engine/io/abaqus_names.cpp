#include "engine/io/abaqus_names.hpp"

#include <algorithm>
#include <cctype>

namespace tubemesh::io {

namespace {

constexpr std::size_t kMaxLabel = 80;

bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool is_label_char(char c) { return is_letter(c) || (c >= '0' && c <= '9') || c == '_'; }

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

std::string valid_label(const std::string& name) {
    std::string s = name;
    std::replace_if(s.begin(), s.end(), [](char c) { return !is_label_char(c); }, '_');
    if (s.empty() || !is_letter(s.front())) s.insert(0, "G_");
    if (s.size() > kMaxLabel) s.resize(kMaxLabel);
    return s;
}

}  // namespace

std::string AbaqusLabels::label(const std::string& name) {
    const std::string base = valid_label(name);
    std::string candidate = base;
    for (int n = 2; taken_.count(upper(candidate)) != 0; ++n) {
        const std::string number = std::to_string(n);
        candidate = base.substr(0, kMaxLabel - number.size() - 1);
        candidate += '_';
        candidate += number;
    }
    taken_.insert(upper(candidate));
    return candidate;
}

}  // namespace tubemesh::io
