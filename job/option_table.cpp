#include "job/option_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "engine/core/types.hpp"
#include "engine/io/mesh_io.hpp"
#include "geom/sizing/discretize_edges.hpp"
#include "job/mesh_settings.hpp"
#include "job/outputs.hpp"

namespace tubemesh::job {

namespace {

using T = OptionType;
using json = nlohmann::json;

OptionSpec number(std::string key, std::string value_name, Range r, json fallback, std::string default_text,
                  std::string help, std::string units = "") {
    OptionSpec s{.key = std::move(key), .type = T::Number, .lo = r.lo, .hi = r.hi, .fallback = std::move(fallback),
                 .default_text = std::move(default_text), .help = std::move(help), .units = std::move(units),
                 .value_name = std::move(value_name)};
    return s;
}
OptionSpec positive(std::string key, std::string value_name, std::string default_text, std::string help,
                    std::string units = "") {
    OptionSpec s = number(std::move(key), std::move(value_name), {0, HUGE_VAL}, nullptr, std::move(default_text),
                          std::move(help), std::move(units));
    s.above_lo = true;
    return s;
}
OptionSpec whole(std::string key, std::string value_name, Range r, json fallback, std::string default_text,
                 std::string help) {
    OptionSpec s = number(std::move(key), std::move(value_name), r, std::move(fallback), std::move(default_text),
                          std::move(help));
    s.type = T::Whole;
    return s;
}
OptionSpec on_off(std::string key, std::string default_text, std::string help) {
    return {.key = std::move(key), .type = T::Switch, .fallback = false, .default_text = std::move(default_text),
            .help = std::move(help)};
}
OptionSpec text(std::string key, T type, std::string value_name, json fallback, std::string default_text,
                std::string help, unsigned shown) {
    return {.key = std::move(key), .type = type, .fallback = std::move(fallback),
            .default_text = std::move(default_text), .help = std::move(help), .shown = shown,
            .value_name = std::move(value_name)};
}
OptionSpec shown_in(OptionSpec s, unsigned shown) {
    s.shown = shown;
    return s;
}
OptionSpec added_later(OptionSpec s) {
    s.hashed = Hashed::WhenChanged;
    return s;
}

std::vector<OptionSpec> make_table() {
    const MeshSettings d;
    const MeshOptions& m = default_mesh_options();
    std::vector<OptionSpec> t;
    t.push_back(positive("size", "S", "bounding-box diagonal / 25, at least 1.3 St", "Overall mesh size S", "length"));
    t.push_back(positive("sweep_size", "St", "smallest tube diameter, cut by the paper's rules",
                         "Hex ring thickness St (a given St the rules would cut is an error)", "length"));
    t.push_back(whole("circ", "N", kCircRange, nullptr, "the multiple of 4 nearest 2 pi (r + St/2) / St, at least 8",
                      "Nodes around each tube, n"));
    t.push_back(whole("layers", "L", kLayersRange, d.layers, fmt::format("{}, graded {} towards the wall", d.layers,
                                                                         m.sweep.grading),
                      "Hex layers across the ring, L"));
    t.push_back(number("axial_aspect", "A", kAxialAspectRange, d.axial_aspect, fmt::format("{}", d.axial_aspect),
                       "Axial step of the hex rings over the side of the ring's outer polygon"));
    t.push_back(number("chordal", "C", kChordalRange, d.chordal,
                       fmt::format("{}: a segment turns by at most {:.3f} rad", d.chordal, geom::chordal_turn(d.chordal)),
                       "Curved CAD edges: largest gap between a chord and the curve over the chord's length"));
    t.push_back(added_later(on_off("economy", "off",
                       fmt::format("The paper's economy: {} nodes around each tube in {} hex layers, St = {} S (at most "
                                   "12.5 tube radii, cut by the rules), axial step {} x the ring's outer side, curved "
                                   "edges to chordal {}, one St for every tube; about half the default's elements. "
                                   "Options given beside it win",
                                   kEconomy.circumferential, kEconomy.layers, kEconomy.sweep_share,
                                   kEconomy.axial_aspect, kEconomy.chordal))));
    t.push_back(number("pyramid_height", "F", kPyramidHeightRange, d.pyramid_height,
                       fmt::format("{}, the paper's", d.pyramid_height), "Pyramid apex height over the quad's mean edge"));
    t.push_back(number("gradation", "G", kGradationRange, d.gradation, fmt::format("{}", d.gradation),
                       "Largest growth of the tet size from one element to the next"));
    t.push_back(shown_in(whole("threads", "T", kThreadsRange, nullptr, "all cores",
                               "Worker threads (more than the cores are not used; the batch sets them per block)"),
                         kCli | kPython));
    t.push_back(whole("tet_parts", "P", kTetPartsRange, d.tet_parts,
                      fmt::format("{}: the mesh is the same for any threads", d.tet_parts),
                      "Spatial parts of the tet step's parallel Delaunay passes (0: one per thread, the mesh then "
                      "depends on the threads)"));
    t.push_back(whole("tet_relax", "R", kTetRelaxRange, d.tet_relax, fmt::format("{}", d.tet_relax),
                      "ODT relaxation rounds of the tet step's interior points before the optimisation (0: none, "
                      "mean collapse about 0.007 lower on the serpentine lift); the far field's lattice points stay "
                      "where they are"));
    t.push_back(on_off("move_apexes", "off: apexes stay where the pyramid layer put them",
                       "Let the tet optimisation move the pyramid apexes, each pyramid kept at a scaled Jacobian of "
                       "at least 0.5: the tets' minimum and mean rise, the pyramids' fall"));
    OptionSpec global = on_off("global_ring",
                               "off: St stays and each ring thins only where a face or another pipe comes near it",
                               "One ring thickness St for every tube, cut by the paper's rules for the closest place "
                               "of all");
    global.aliases = {{"local_ring", true, kPython | kManifest}};
    global.hash_name = "local_ring";
    t.push_back(global);
    t.push_back(added_later(on_off(
        "scale_free", "off: the geometry is handed to the mesher as read",
        "Round every length, position, direction and parameter handed to the mesher to 2^-26 of the solid's "
        "diagonal, so one solid at another scale (1e-6, 1, 1e6) or rounded otherwise by its CAD export meshes "
        "alike up to the scale (so far where the tubes are straight or circular); the rounding changes every "
        "mesh's tie-breaks. Not with assembly")));
    OptionSpec fixed = on_off("fixed_surface", "off: the tet optimisation slides the nodes inside flat faces in their plane",
                              "Keep every surface node where the surface mesher put it (nodes on CAD edges, curved "
                              "faces, rings and pyramids stay either way)");
    fixed.aliases = {{"slide_surface", true, kPython | kManifest}};
    fixed.hash_name = "slide_surface";
    t.push_back(fixed);
    t.push_back(positive("max_elements", "N", "what the memory this process may use holds (lower bound only)",
                         "Refuse sizes that give more elements (cells and boundary faces) than this, before meshing "
                         "and after each stage; no mesh over it is written",
                         "elements"));
    t.push_back(whole("solid", "K", kSolidRange, nullptr, "the file's only solid",
                      "Which solid of the file, 1-based (when it holds several)"));
    t.push_back(text("until", T::Text, "STAGE", nullptr, "the last stage",
                     "Last stage to run: " + stage_names() + " (partial stages are checked for what they hold)",
                     kCli | kPython));
    t.push_back(added_later(on_off("assembly", "off",
                                   "The CAD file holds several solids that share faces (or touch within "
                                   "glue_tolerance): mesh them as one conforming mesh, a volume group per solid")));
    t.push_back(added_later(positive("glue_tolerance", "D", "1e-6 of the assembly's bounding-box diagonal",
                                     "With assembly: faces of different solids this close are glued; a wider gap or "
                                     "overlap is an error",
                                     "length")));
    t.push_back(text("output", T::TextList, "OUT", json::array(), "none (see Quick start)",
                     "Mesh file to write (.msh, .vtu, .vtm, .inp, by extension); repeat for several",
                     kCli | kPython));
    t.back().flag = "-o,--output";
    t.push_back(text("report", T::Text, "FILE.json", "", "none", "Also write the report as JSON to this file",
                     kCli | kPython));
    t.push_back(text("html", T::Text, "FILE.html", "", "none",
                     "Also write the report as one self-contained HTML page", kCli | kPython));
    OptionSpec formats = text("formats", T::TextList, "LIST", json::array({"msh"}), "msh",
                              "A block's files: msh, vtu, inp and html (the block's HTML report)", kManifest);
    formats.choices = {"msh", "vtu", "inp", "html"};
    t.push_back(formats);
    t.push_back(added_later(on_off("msh_ascii", "off: binary", "Write .msh files as text")));
    OptionSpec family = text("inp_family", T::Choice, "FAMILY", kInpFamilies[0], kInpFamilies[0],
                             "Element family of .inp files: stress (C3D4/C3D8; CalculiX uses them for heat transfer too), heat "
                             "(DC3D4/DC3D8, Abaqus and CalculiX), coupled (coupled temperature-displacement for "
                             "CalculiX: C3D4/C3D8, which its coupled step gives the temperature), coupled-abaqus "
                             "(C3D4T/C3D8T: Abaqus only, CalculiX refuses them)",
                             kAllFrontEnds);
    family.choices = kInpFamilies;
    t.push_back(added_later(family));
    OptionSpec pyramid = text("inp_pyramid", T::Choice, "FORM", kInpPyramids[0], kInpPyramids[0],
                              "Pyramids in .inp files: hex (a C3D8 with the apex repeated, which CalculiX and Abaqus read) or "
                              "c3d5 (the 5-node pyramid, stress family only: Abaqus only, CalculiX refuses it)",
                              kAllFrontEnds);
    pyramid.choices = kInpPyramids;
    t.push_back(added_later(pyramid));
    t.push_back(on_off("pipe_network", "off",
                       "Write the water in every pipe into the .inp as a CalculiX fluid network and X.films.inp "
                       "beside X.inp"));
    OptionSpec film = positive("film_coefficient", "H", "2000 (water at about 0.5 m/s in a 25 mm pipe)",
                               "With pipe_network: h of the wall faces' films, in the deck's units", "W/(m2 K)");
    film.fallback = PipeNetworkOptions{}.film_coefficient;
    t.push_back(film);
    OptionSpec reverse = whole("reverse_flow", "K", {1, 1e9}, json::array(), "none",
                               "With pipe_network: the water of pipe_<k> enters at its second end; a list (repeat "
                               "the flag)");
    reverse.type = T::WholeList;
    t.push_back(reverse);
    t.push_back(shown_in(on_off("quiet", "off", "Print nothing but errors"), kCli));
    OptionSpec limit = number("time_limit", "S", {0, HUGE_VAL}, 3600.0, "3600 (0: none)",
                              "Seconds a block may take", "s");
    limit.shown = kManifest;
    limit.hashed = Hashed::Never;
    t.push_back(limit);
#ifdef TUBEMESH_TEST_DUMMY_OPTION
    // A test build's extra option: every front end must show it without any other change.
    t.push_back(added_later(number("dummy_option", "X", {0, 1}, 0.5, "0.5", "An option only the test build has")));
#endif
    for (OptionSpec& s : t)
        if (s.flag.empty()) s.flag = flag_spelling(s.key);
    return t;
}

}  // namespace

const std::vector<OptionSpec>& option_table() {
    static const std::vector<OptionSpec> table = make_table();
    return table;
}

const OptionSpec* find_option(std::string_view key) {
    for (const OptionSpec& s : option_table())
        if (s.key == key) return &s;
    return nullptr;
}

NamedOption option_named(std::string_view name, Shown where) {
    for (const OptionSpec& s : option_table()) {
        if (!(s.shown & where)) continue;
        if (s.key == name) return {&s, nullptr};
        for (const OptionAlias& a : s.aliases)
            if ((a.shown & where) && name == a.name) return {&s, &a};
    }
    return {};
}

json value_from_alias(const NamedOption& named, const json& value) {
    if (named.alias && named.alias->inverted && value.is_boolean()) return !value.get<bool>();
    return value;
}

std::string flag_spelling(std::string_view key) {
    std::string flag = "--" + std::string(key);
    for (char& c : flag)
        if (c == '_') c = '-';
    return flag;
}

std::string deprecation_message(const NamedOption& named, Shown where) {
    const auto spell = [&](std::string_view k) { return where == kCli ? flag_spelling(k) : "\"" + std::string(k) + "\""; };
    return fmt::format("{} is deprecated: use {}{}", spell(named.alias->name), spell(named.spec->key),
                       named.alias->inverted ? " (the opposite: true there is false here)" : "");
}

void check_option_type(const OptionSpec& s, const std::string& name, const json& v, const std::string& where) {
    const auto fail = [&](const std::string& what) {
        throw Error(fmt::format("{}: \"{}\" {}, got {}", where, name, what, v.dump()));
    };
    const bool automatic = v.is_null() && s.fallback.is_null();
    switch (s.type) {
    case T::Switch:
        if (!v.is_boolean()) fail("must be true or false");
        return;
    case T::Text:
        if (!v.is_string()) fail("must be a string");
        return;
    case T::Choice:
        if (!v.is_string()) fail("must be one of " + json(s.choices).dump());
        return;
    case T::TextList:
        if (!v.is_array() || (!s.choices.empty() && v.empty())) fail("must be a list of strings");
        for (const json& e : v)
            if (!e.is_string() || (!s.choices.empty() && std::find(s.choices.begin(), s.choices.end(),
                                                                   e.get<std::string>()) == s.choices.end()))
                throw Error(fmt::format("{}: \"{}\" takes {}, got {}", where, name, json(s.choices).dump(), e.dump()));
        return;
    case T::WholeList:
        if (!v.is_array()) fail("must be a list of whole numbers");
        for (const json& e : v)
            if (!e.is_number_integer())
                throw Error(fmt::format("{}: \"{}\" takes whole numbers, got {}", where, name, e.dump()));
        return;
    case T::Number:
    case T::Whole:
        if (automatic) return;
        if (!(v.is_number() && std::isfinite(v.get<double>())))
            fail(std::string("must be a number") + (s.fallback.is_null() ? " or null (automatic)" : ""));
        // Whole numbers become ints: beyond that range they are out of every option's range anyway.
        if (s.type == T::Whole && (v.get<double>() != std::floor(v.get<double>()) || std::abs(v.get<double>()) > 1e9))
            fail("must be a whole number of at most 1e9");
        return;
    }
}

}  // namespace tubemesh::job
