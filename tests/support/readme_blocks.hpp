#pragma once
// The README's tested code blocks: the text between "<!-- NAME -->\n```\n" and
// "```\n<!-- /NAME -->", which tests run as written. TUBEMESH_SOURCE_DIR is a compile
// definition of the targets that read it.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace tubemesh::testing {

// Empty, and a test failure, when the README has no such block.
inline std::string readme_block(const std::string& name) {
    std::ifstream readme(std::string(TUBEMESH_SOURCE_DIR) + "/README.md");
    std::stringstream text;
    text << readme.rdbuf();
    const std::string s = text.str();
    const std::string begin = "<!-- " + name + " -->\n```\n", end = "```\n<!-- /" + name + " -->";
    const std::size_t from = s.find(begin), to = s.find(end);
    if (from == std::string::npos || to == std::string::npos || to < from) {
        ADD_FAILURE() << "README has no " << name << " block";
        return "";
    }
    return s.substr(from + begin.size(), to - from - begin.size());
}

}  // namespace tubemesh::testing
