// README's option table from the option table (job/option_table.hpp); a test compares the two.
#include <fmt/format.h>

#include "job/option_table.hpp"

namespace tubemesh::job {

namespace {

std::string cell(const OptionSpec& s, Shown where) {
    if (!(s.shown & where)) return "–";
    std::string text = where == kCli ? "`" + s.flag + (s.type == OptionType::Switch ? "" : " " + s.value_name) + "`"
                                     : "`" + s.key + "`";
    for (const OptionAlias& a : s.aliases)
        if (a.shown & where)
            text += fmt::format(" (was `{}`{})", where == kCli ? flag_spelling(a.name) : std::string(a.name),
                                a.inverted ? ", the opposite" : "");
    return text;
}

}  // namespace

std::string option_table_markdown() {
    std::string out = "| command line | Python | manifest | default | units | meaning |\n|---|---|---|---|---|---|\n";
    for (const OptionSpec& s : option_table())
        out += fmt::format("| {} | {} | {} | {} | {} | {} |\n", cell(s, kCli), cell(s, kPython), cell(s, kManifest),
                           s.default_text, s.units.empty() ? "–" : s.units, s.help);
    return out;
}

}  // namespace tubemesh::job
