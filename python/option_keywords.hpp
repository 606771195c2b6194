#pragma once
// The Python keywords of the option table (job/option_table.hpp): tubemesh.mesh's signature and
// docstring are made from it, and its keywords become {key: value} for job::job_settings.
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <string>

namespace tubemesh::python {

// {key: value} of the keywords given (None: not given). An older spelling issues a FutureWarning
// and becomes its option's key; an unknown keyword or a value of the wrong type raises
// tubemesh.Error naming it.
nlohmann::json given_options(const pybind11::dict& keywords);

// Defines `name` on the module as a Python function (source=default_source, *, <every option
// the table shows in Python>, progress=None) that calls impl(source, {keyword: value}, progress),
// with the table's signature (inspect.signature) and a docstring of `summary` then one line per
// option.
void define_with_options(pybind11::module_& m, const char* name, pybind11::cpp_function impl,
                         const char* default_source, const std::string& summary, const std::string& closing);

// The docstring's option lines: "size=None: Overall mesh size S (default: ...; length)".
std::string option_lines();

}  // namespace tubemesh::python
