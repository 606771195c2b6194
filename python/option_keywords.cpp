#include "python/option_keywords.hpp"

#include <fmt/format.h>
#include <pybind11/eval.h>

#include "engine/core/types.hpp"
#include "job/job_settings.hpp"
#include "job/option_table.hpp"

namespace py = pybind11;

namespace tubemesh::python {

namespace {

using json = nlohmann::json;

json to_json(const py::handle& v, const std::string& name) {
    if (v.is_none()) return nullptr;
    if (py::isinstance<py::bool_>(v)) return v.cast<bool>();
    if (py::isinstance<py::int_>(v)) return v.cast<long long>();
    if (py::isinstance<py::float_>(v)) return v.cast<double>();
    if (py::isinstance<py::str>(v)) return v.cast<std::string>();
    if (py::hasattr(v, "__fspath__")) return py::str(py::module_::import("os").attr("fspath")(v)).cast<std::string>();
    if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
        json out = json::array();
        for (const py::handle& e : v) out.push_back(to_json(e, name));
        return out;
    }
    throw Error(fmt::format("{} takes numbers, True or False, strings, paths or lists of them, got a {}", name,
                            py::str(py::type::of(v).attr("__name__")).cast<std::string>()));
}

py::object python_default(const job::OptionSpec& s) {
    return py::module_::import("json").attr("loads")(s.fallback.dump());
}

}  // namespace

json given_options(const py::dict& keywords) {
    json named = json::object();
    for (const auto& [k, v] : keywords) {
        const std::string name = py::str(k);
        json value = to_json(v, name);
        if (value.is_null()) continue;  // None: automatic, as when left out
        const job::NamedOption o = job::option_named(name, job::kPython);
        // One path where a list of them is asked for.
        if (o.spec && o.spec->type == job::OptionType::TextList && value.is_string()) value = json::array({value});
        named[name] = value;
    }
    try {
        return job::canonical_options(named, job::kPython, "mesh()", [](const std::string& message) {
            py::module_::import("warnings").attr("warn")(message, py::handle(PyExc_FutureWarning), 2);
        });
    } catch (const Error& e) {
        // "mesh(): \"x\" must be ..." -> "x must be ..." (the keyword as the caller wrote it).
        std::string m = e.what();
        if (m.starts_with("mesh(): \"")) {
            const std::size_t end = m.find('"', 9);
            m = m.substr(9, end - 9) + m.substr(end + 1);
        }
        if (const std::size_t at = m.find(" or null (automatic)"); at != std::string::npos)
            m.replace(at, 20, " or None (automatic)");
        throw Error(m);
    }
}

std::string option_lines() {
    std::string out;
    for (const job::OptionSpec& s : job::option_table()) {
        if (!(s.shown & job::kPython)) continue;
        std::string line = fmt::format("{}={}: {} (default: {}", s.key, py::repr(python_default(s)).cast<std::string>(),
                                       s.help, s.default_text);
        if (!s.units.empty()) line += "; " + s.units;
        line += ")";
        for (const job::OptionAlias& a : s.aliases)
            if (a.shown & job::kPython) line += fmt::format(" [was {}{}]", a.name, a.inverted ? ", the opposite" : "");
        out += line + "\n";
    }
    return out;
}

void define_with_options(py::module_& m, const char* name, py::cpp_function impl, const char* default_source,
                         const std::string& summary, const std::string& closing) {
    py::object inspect = py::module_::import("inspect");
    py::object parameter = inspect.attr("Parameter");
    py::list params;
    params.append(parameter("source", parameter.attr("POSITIONAL_OR_KEYWORD"), py::arg("default") = default_source));
    for (const job::OptionSpec& s : job::option_table())
        if (s.shown & job::kPython)
            params.append(parameter(s.key, parameter.attr("KEYWORD_ONLY"), py::arg("default") = python_default(s)));
    params.append(parameter("progress", parameter.attr("KEYWORD_ONLY"), py::arg("default") = py::none()));

    py::dict scope;
    scope["_impl"] = impl;
    scope["_default_source"] = default_source;
    py::exec(fmt::format(R"(
def {0}(source=_default_source, *, progress=None, **options):
    return _impl(source, options, progress)
)",
                         name),
             scope);
    py::object f = scope[name];
    f.attr("__signature__") = inspect.attr("Signature")(params);
    f.attr("__doc__") = summary + "\n\nOptions (None: automatic):\n" + option_lines() + "\n" + closing;
    f.attr("__module__") = m.attr("__name__");
    f.attr("__qualname__") = name;
    m.attr(name) = f;
}

}  // namespace tubemesh::python
