#pragma once
// Every option of a mesh job, once: its key, command-line flag, type, range, default, help, units
// and the front ends that show it. The command line's flags (tools/cli/option_flags.cpp), the
// Python keywords and docstring (python/option_keywords.cpp), the batch manifest's keys
// (batch/block_options.cpp) and README's option table (option_table_markdown) are made from it,
// so an option has one name and one default everywhere. An older spelling stays as an alias that
// works with a deprecation warning.
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace tubemesh::job {

enum class OptionType {
    Number,     // a finite number in [lo, hi] (above lo when above_lo)
    Whole,      // a whole number in [lo, hi]
    Switch,     // true or false; a flag without value on the command line
    Choice,     // one of `choices`
    Text,       // a string (a path, a stage name)
    WholeList,  // whole numbers in [lo, hi], the flag repeated on the command line
    TextList,   // strings (paths, formats), the flag repeated on the command line
};

// Which front ends show an option (bits).
enum Shown : unsigned { kCli = 1, kPython = 2, kManifest = 4, kAllFrontEnds = 7 };

// An older name of an option, shown where `shown` says. inverted: it meant the opposite switch
// (slide_surface=True is fixed_surface=False).
struct OptionAlias {
    const char* name;  // key spelling ("slide_surface"); on the command line "--" + dashes
    bool inverted;
    unsigned shown;
};

// How the batch's options hash takes an option: Always (the options hashed before the table),
// WhenChanged (added later: hashed only away from its default, so a block's hash stays what it
// was), Never (time_limit: it does not change the mesh).
enum class Hashed { Always, WhenChanged, Never };

struct OptionSpec {
    std::string key;           // the Python keyword and the manifest key
    std::string flag;          // the command line: "--size", "-o,--output"
    OptionType type;
    double lo = 0, hi = 0;     // the range of Number, Whole, WholeList
    bool above_lo = false;     // Number: lo itself is refused (a positive number)
    nlohmann::json fallback;   // the default; null: automatic
    std::string default_text;  // the default as users read it
    std::string help;          // one or two sentences, without the default
    std::string units;         // "" when it has none
    unsigned shown = kAllFrontEnds;
    std::string value_name;    // "S": "--size S" in the help and README
    std::vector<std::string> choices;  // Choice
    std::vector<OptionAlias> aliases;
    Hashed hashed = Hashed::Always;
    std::string hash_name;     // the name the hash knows it by ("" : key); an alias's, inverted as it is
};

// Every option, in the order the help lists them.
const std::vector<OptionSpec>& option_table();

// The option of that key; nullptr for none.
const OptionSpec* find_option(std::string_view key);

// A name as a front end got it: the option and, for an older spelling, its alias.
struct NamedOption {
    const OptionSpec* spec = nullptr;  // nullptr: no such option there
    const OptionAlias* alias = nullptr;
};
NamedOption option_named(std::string_view name, Shown where);

// The option's value by its alias: a switch's inverted, anything else as it is.
nlohmann::json value_from_alias(const NamedOption& named, const nlohmann::json& value);

// Checks the type of one value (ranges: job_settings): throws tubemesh::Error
// "<where>: \"<name>\" must be ..." naming the option as the user wrote it. null is accepted
// where the option is automatic.
void check_option_type(const OptionSpec& spec, const std::string& name, const nlohmann::json& value,
                       const std::string& where);

// "--fixed-surface" from "fixed_surface" (the key's spelling on the command line).
std::string flag_spelling(std::string_view key);

// The message for an older spelling: "\"slide_surface\" is deprecated: use \"fixed_surface\" ...".
std::string deprecation_message(const NamedOption& named, Shown where);

// README's option table (Markdown), one row per option: flag, Python and manifest key, default,
// units and help.
std::string option_table_markdown();

}  // namespace tubemesh::job
