#include "bench/reference_cases.hpp"

#include <map>
#include <memory>

#include "geom/builders/presets.hpp"

namespace tubemesh::bench {

namespace {
constexpr ReferenceCase kCases[] = {
    {"paper-ex1", "paper-ex1", 0.6},       {"paper-ex2", "paper-ex2", 1.1},
    {"paper-ex3", "paper-ex3", 40},        {"serpentine-lift", "serpentine-lift", 0},
    {"dam-block", "paper-ex1", 0},         {kLargeLift, "serpentine-lift", 0.11},
};
}  // namespace

std::span<const ReferenceCase> reference_cases() { return kCases; }

const ReferenceCase& reference_case(std::string_view name) {
    for (const ReferenceCase& c : kCases)
        if (name == c.name) return c;
    throw Error("no reference case named " + std::string(name));
}

const geom::BuiltBlock& built_block(const ReferenceCase& c) {
    static std::map<std::string, std::unique_ptr<geom::BuiltBlock>> cache;
    auto& b = cache[c.preset];
    if (!b) b = std::make_unique<geom::BuiltBlock>(geom::build_block(geom::preset_spec(c.preset)));
    return *b;
}

MeshOptions case_options(const ReferenceCase& c, int threads) {
    MeshOptions options;
    options.size = c.size;
    options.threads = threads;
    return options;
}

const geom::PreparedModel& prepared_case(const ReferenceCase& c) {
    static std::string current_name;
    static std::unique_ptr<geom::PreparedModel> current;
    if (!current || current_name != c.name) {
        current.reset();
        current = std::make_unique<geom::PreparedModel>(
            geom::prepare_model(built_block(c).model, geom::prepare_options(case_options(c, 0))));
        current_name = c.name;
    }
    return *current;
}

}  // namespace tubemesh::bench
