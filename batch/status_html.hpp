#pragma once
// `tubemesh batch --status OUTDIR --html FILE`: the catalogue as one self-contained page in the
// run reports' style (job/html_report.hpp): a summary, elements, tet quality and time per
// block as bar charts, and the blocks' table with a link to each block's own report where the
// batch wrote one (format "html").
#include <string>
#include <vector>

#include "batch/catalogue.hpp"

namespace tubemesh::batch {

std::string status_html(const std::vector<BlockRecord>& rows);

}  // namespace tubemesh::batch
