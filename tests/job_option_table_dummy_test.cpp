// The option table drives the three front ends: this test's build adds an option to the table
// (TUBEMESH_TEST_DUMMY_OPTION, job/option_table.cpp compiled into it) and finds it in the
// command line's help, the Python signature and docstring, and the manifest's schema, with
// nothing else changed.
#include <gtest/gtest.h>
#include <pybind11/embed.h>

#include "batch/block_options.hpp"
#include "python/option_keywords.hpp"
#include "tools/cli/option_flags.hpp"

namespace tubemesh {
namespace {

namespace py = pybind11;

TEST(DummyOption, InTheCommandLinesHelpAndParsed) {
    CLI::App app;
    CLI::App* cmd = app.add_subcommand("mesh");
    cli::OptionFlags flags;
    flags.add_to(cmd);
    EXPECT_NE(cmd->help().find("--dummy-option X"), std::string::npos) << cmd->help();
    EXPECT_NE(cmd->help().find("An option only the test build has (default: 0.5)"), std::string::npos);
    app.parse(std::vector<std::string>{"0.25", "--dummy-option", "mesh"});  // CLI11 takes them reversed
    EXPECT_EQ(flags.given().at("dummy_option"), 0.25);
}

TEST(DummyOption, InThePythonSignatureAndDocstring) {
    py::scoped_interpreter python;
    py::module_ m = py::reinterpret_borrow<py::module_>(py::module_::import("types").attr("ModuleType")("dummy"));
    python::define_with_options(
        m, "mesh", py::cpp_function([](py::object, py::dict options, py::object) { return options; }), "paper-ex1",
        "Summary.", "Closing.");
    const std::string signature = py::str(py::module_::import("inspect").attr("signature")(m.attr("mesh")));
    EXPECT_NE(signature.find("dummy_option=0.5"), std::string::npos) << signature;
    const std::string doc = py::str(m.attr("mesh").attr("__doc__"));
    EXPECT_NE(doc.find("dummy_option=0.5: An option only the test build has"), std::string::npos) << doc;
    py::dict options = m.attr("mesh")("paper-ex1", py::arg("dummy_option") = 0.75);
    EXPECT_EQ(python::given_options(options).at("dummy_option"), 0.75);
}

TEST(DummyOption, InTheManifestsSchemaAndAccepted) {
    EXPECT_EQ(batch::manifest_schema().at("dummy_option").at("default"), 0.5);
    EXPECT_EQ(batch::default_block_options().at("dummy_option"), 0.5);
    const nlohmann::json merged =
        batch::merge_block_options(batch::default_block_options(), {{"dummy_option", 0.25}}, "block b");
    EXPECT_EQ(merged.at("dummy_option"), 0.25);
    EXPECT_THROW(batch::merge_block_options(batch::default_block_options(), {{"dummy_option", "x"}}, "block b"), Error);
}

}  // namespace
}  // namespace tubemesh
