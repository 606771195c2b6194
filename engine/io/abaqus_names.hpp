#pragma once
// Set and surface names for Abaqus input files. Abaqus labels start with a letter, hold
// letters, digits and underscores, are at most 80 characters long and ignore case; tubemesh's
// group names ("hex_ring", "pipe_1") already fit, anything else is made to fit.
#include <set>
#include <string>

namespace tubemesh::io {

// Hands out distinct labels within one Abaqus namespace (element sets, node sets or
// surfaces each have their own).
class AbaqusLabels {
public:
    // `name` made valid: other characters become '_', a leading non-letter gets "G_" before
    // it, long names are cut; a label already given (ignoring case) gets "_2", "_3", ...
    std::string label(const std::string& name);

private:
    std::set<std::string> taken_;  // upper case
};

}  // namespace tubemesh::io
