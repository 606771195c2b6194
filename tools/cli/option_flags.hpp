#pragma once
// The command line's flags of the option table (job/option_table.hpp): every option the table
// shows on the command line becomes a flag with its name, type, range check, help and default;
// after parsing, given() holds what the user gave as {key: value} for job::job_settings.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <deque>
#include <string>
#include <variant>
#include <vector>

#include "job/option_table.hpp"

namespace tubemesh::cli {

class OptionFlags {
public:
    // Adds the flags to `cmd`. The object must outlive the parse.
    void add_to(CLI::App* cmd);

    // {key: value} of the flags given (older spellings warned about on stderr and turned into
    // their option's key).
    nlohmann::json given() const;

private:
    using Value = std::variant<double, long long, bool, std::string, std::vector<long long>, std::vector<std::string>>;
    struct Slot {
        const job::OptionSpec* spec;
        const job::OptionAlias* alias;  // nullptr: the option's own flag
        CLI::Option* option;
        Value value;
    };
    std::deque<Slot> slots_;  // stable addresses: CLI11 binds to them
};

}  // namespace tubemesh::cli
