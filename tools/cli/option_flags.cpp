#include "tools/cli/option_flags.hpp"

#include <fmt/format.h>

#include <cmath>

#include "tools/cli/option_checks.hpp"

namespace tubemesh::cli {

namespace {

using Value = std::variant<double, long long, bool, std::string, std::vector<long long>, std::vector<std::string>>;

using job::OptionType;

std::string help_of(const job::OptionSpec& s) {
    return s.default_text.empty() ? s.help : fmt::format("{} (default: {})", s.help, s.default_text);
}

CLI::Validator range_check(const job::OptionSpec& s) {
    if (s.type == OptionType::Whole || s.type == OptionType::WholeList)
        return whole_number(static_cast<long long>(s.lo), static_cast<long long>(s.hi));
    if (s.above_lo && s.lo == 0) return positive_number();
    return number_between(s.lo, std::isinf(s.hi) ? 1e300 : s.hi);
}

CLI::Option* add(CLI::App* cmd, const std::string& names, const job::OptionSpec& s, Value& v,
                 const std::string& help) {
    switch (s.type) {
    case OptionType::Switch:
        return cmd->add_flag(names, v.emplace<bool>(false), help);
    case OptionType::Number:
        return cmd->add_option(names, v.emplace<double>(0), help)->check(range_check(s))->option_text(s.value_name);
    case OptionType::Whole:
        return cmd->add_option(names, v.emplace<long long>(0), help)->check(range_check(s))->option_text(s.value_name);
    case OptionType::Choice:
        return cmd->add_option(names, v.emplace<std::string>(), help)->check(CLI::IsMember(s.choices));
    case OptionType::Text:
        return cmd->add_option(names, v.emplace<std::string>(), help)->option_text(s.value_name);
    case OptionType::WholeList:
        // One value per flag: the next word may be the input file. The job checks the values (a
        // message that says what they number).
        return cmd->add_option(names, v.emplace<std::vector<long long>>(), help)
            ->option_text(s.value_name)
            ->allow_extra_args(false)
            ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    case OptionType::TextList:
        return cmd->add_option(names, v.emplace<std::vector<std::string>>(), help)
            ->option_text(s.value_name)
            ->allow_extra_args(false);  // `-o a.msh IN` must not take IN as a second output
    }
    return nullptr;
}

}  // namespace

void OptionFlags::add_to(CLI::App* cmd) {
    for (const job::OptionSpec& s : job::option_table()) {
        if (!(s.shown & job::kCli)) continue;
        Slot& own = slots_.emplace_back(Slot{&s, nullptr, nullptr, {}});
        own.option = add(cmd, s.flag, s, own.value, help_of(s));
        for (const job::OptionAlias& a : s.aliases) {
            if (!(a.shown & job::kCli)) continue;
            Slot& old = slots_.emplace_back(Slot{&s, &a, nullptr, {}});
            old.option = add(cmd, job::flag_spelling(a.name), s, old.value, "")->group("");  // hidden
        }
    }
}

nlohmann::json OptionFlags::given() const {
    nlohmann::json out = nlohmann::json::object();
    for (const Slot& slot : slots_) {
        if (slot.option->count() == 0) continue;
        nlohmann::json v;
        std::visit([&](const auto& x) { v = x; }, slot.value);
        if (slot.alias) {
            const job::NamedOption named{slot.spec, slot.alias};
            fmt::print(stderr, "tubemesh: warning: {}\n", job::deprecation_message(named, job::kCli));
            v = job::value_from_alias(named, v);
        }
        out[slot.spec->key] = v;
    }
    return out;
}

}  // namespace tubemesh::cli
