#pragma once
// The pyramid layer (paper §4): one pyramid on every outer quad of the hex rings, so the
// tetrahedra of the rest of the solid meet the rings through triangles.
//
// An advancing front (advancing_front.hpp). Each front quad tries the ideal apex
// N = M + 0.98154·h·n, then the existing front nodes near N; a candidate is accepted when the
// validity and suitability criteria of §4 Step 4 hold (criteria.hpp). Fronts rejected by that
// pass are retried with try nodes on the normal line and relaxed criteria (Steps 5-8); fronts
// rejected even then get a drawback: the pyramids around them are deleted and the fronts
// retried, the rejected ones first and with their smallest try node first. Where two
// pyramids share an apex, their common triangle is a face of both and leaves the front.
//
// Added to the paper, each for a reason given where it is implemented: a quality floor
// (options below), a refusal of existing apexes that would make the front non-manifold
// (front_link.hpp), a precise reading of the edge-distance criterion (criteria.hpp), try
// nodes moved off the faces they are too close to, tried last (candidates.hpp), and a lower,
// shifted ideal apex for quads with an edge on a boundary face (wedge.hpp).
//
// Fronts whose search spheres do not overlap cannot see each other's work, so they are
// evaluated in parallel in conflict-free batches (batches.hpp) and committed in a fixed
// order: the mesh is the same for every thread count.
//
// Orientation conventions (right-hand rule on the listed node order):
//  * front quads: the normal points away from the ring, INTO the tet region (the hex's own
//    outward face). The pyramid on quad (a,b,c,d) is (a,b,c,d,apex): base counter-clockwise
//    seen from the apex, as the mesh store wants (topology.hpp).
//  * boundary triangles: the normal points OUT of the tet region — the mesh store's
//    boundary-face convention, so surface triangles can be passed straight from the store.
//  * free triangles in the result: the same as the boundary triangles. Together they close
//    the tet region with every normal pointing out of it.
//  * obstacle quads: any orientation (they are only ever tested for intersection).
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/pulse.hpp"
#include "engine/core/types.hpp"
#include "engine/mesh/hybrid_mesh.hpp"

namespace tubemesh {

struct PyramidInput {
    // 4 node ids per quad: the rings' outer lateral quads, each of which gets a pyramid.
    std::span<const index_t> front_quads;
    // 3 node ids per triangle: the surface triangles that, with the pyramids' free
    // triangles, bound the tet region (every B-rep face except the tube walls).
    std::span<const index_t> boundary_triangles;
    // 4 node ids per quad: fixed faces that no new element may cross but that do not bound
    // the tet region, e.g. the rings' end quads on the host faces (they lie inside the
    // ring's outer polygon, where the tet region does not reach). Their nodes are never
    // candidate apexes. Optional.
    std::span<const index_t> obstacle_quads;
    // Region id (index into mesh.region_names) given to the new pyramids.
    index_t region = kNoIndex;
    // Per front quad, its ring's thickness there over St (SweepResult::outer_quad_scale), or
    // empty. Below 1 the front's ideal apex is lowered by that share (a thin ring has a thin
    // gap in front of it) and its quality floor follows the lowered apex, not the paper's.
    std::span<const double> front_scale;
    // The rings' thickness St, which a failure's message names with a value to try; 0: not known.
    double sweep_size = 0;
};

struct PyramidOptions {
    // Ideal apex height over the front's centroid, times the mean edge length h (paper 4.1).
    double height_factor = 0.98154;
    // Existing nodes closer than this times h to the ideal apex are candidates (§4 Step 3); over
    // a thin ring (front_scale) times its share of h, and at most the 32 nearest.
    double search_radius_factor = 1.5;
    // Largest angle between MN and the front normal n (§4 Step 4).
    double max_angle_degrees = 45.0;
    // Not in the paper: a front with an edge on a boundary face (a ring's last-station quad,
    // on the host) whose paper apex leaves a wedge narrower than wedge_degrees between its
    // lateral face over that edge and the boundary triangle there gets its ideal apex at
    // wedge_height_factor·h, shifted along the quad away from the edge until the wedge
    // reaches wedge_degrees, by at most wedge_max_shift of the quad's length (wedge.hpp).
    // The tet filling that wedge has it as a dihedral angle. wedge_degrees = 0 disables it.
    // The paper's candidates leave a narrow wedge on straight pipes square to their hosts; the
    // angle and height are the best found before apexes are refused or oblique end pyramids
    // lose quality (bench/results/tuning-notes.md).
    double wedge_degrees = 48.0;
    double wedge_height_factor = 0.8;
    double wedge_max_shift = 0.3;
    // Not in the paper: where the normal pass refuses that apex (on an oblique pipe end whose
    // host face leans over the end quad, the apex wedge_max_shift allows is too close to the
    // host), a second one placed the same way but shifted by up to wedge_wide_shift of the
    // quad's length is tried before the existing nodes. Those fronts used to take the
    // neighbour's apex (shifted about 0.9 h), whose 34-35 degree wedge held the tet there to
    // collapse 0.26-0.28 (random blocks 85, 96, 116). At 0.7 the more tilted pyramids crowded
    // more of the fronts served after them; raising wedge_max_shift itself instead moves the
    // apexes the normal pass accepts now as well. 0 (or at most wedge_max_shift) disables it.
    double wedge_wide_shift = 0.5;
    // Not in the paper: fronts that share no node but whose ideal apexes lie nearer than
    // apart_factor times their mean h (two rings passing close, their apex layers facing
    // across the gap) have their ideal apexes lowered along their normals together, by the
    // largest factor that puts them that far apart, but to no less than apart_lowest of the
    // height (a front with an apex placed for a wedge keeps it). The first of two facing
    // fronts served used to take the full height and leave the other a low try node near its
    // apex; the tet between four such apexes was the worst of the block (random blocks 60, 74,
    // 79, 131: 0.251-0.296). 0 disables it.
    double apart_factor = 0.9;
    double apart_lowest = 0.6;
    // Smallest distance, times h, from the apex to the front's faces and from the new edges
    // to the front's edges (§4 Step 4).
    double distance_factor = 0.65;
    // Relaxed pass: try node k (k = 1..try_nodes) sits at M + Rate·(N − M) (height_factor·h·Rate
    // above M but for a front placed for a wedge, fronts.hpp) and is judged with max_angle/Rate
    // and distance_factor·h·Rate, Rate = relax_rate^k (§4 Step 8).
    double relax_rate = 0.9;
    int try_nodes = 5;
    // Drawback rounds before giving up with tubemesh::Error (the mesh is then unchanged).
    int max_drawback_rounds = 8;
    // Not in the paper: a candidate whose pyramid scaled Jacobian is below
    // min(min_quality, min_quality_ratio · that of the front's ideal pyramid) is refused, so
    // that a permissive relaxed pass or a node on a nearby face cannot give a sliver, while a
    // quad too elongated for any pyramid to reach min_quality still gets one nearly as good
    // as its ideal. min_quality = 0 disables the check.
    double min_quality = 0.45;
    double min_quality_ratio = 0.8;
    // Called between batches (engine/core/pulse.hpp); may throw to stop the run.
    Pulse pulse;
};

// Why a candidate apex was refused (or that it was accepted). Counted in the statistics.
enum class Verdict : std::uint8_t {
    Accepted,
    AngleTooLarge,    // angle(MN, n) >= max angle
    NotPositive,      // one of the pyramid's four sub-tets is flat or inverted (exact)
    LowQuality,       // scaled Jacobian below the front's quality floor
    FaceMismatch,     // a new triangle repeats a front triangle with the same orientation
    PinchesFront,     // an existing apex would make the front touch itself (non-manifold)
    TooCloseToFace,   // apex nearer than the distance threshold to a front face
    ContainsNode,     // an existing node lies inside the new pyramid (exact)
    TooCloseToEdge,   // a new edge nearer than the distance threshold to a front edge
    EdgeCrossesFace,  // a new edge meets a front face other than at a shared node (exact)
    FaceCrossesEdge,  // a new triangle meets a front edge other than at a shared node (exact)
};
inline constexpr int kVerdictCount = 11;
const char* verdict_name(Verdict v);

struct PyramidStats {
    index_t fronts = 0;
    index_t pyramids = 0;
    // How the final pyramids got their apex.
    index_t ideal = 0;                       // the ideal node, normal criteria
    index_t wide = 0;                        // the wider wedge apex (wedge_wide_shift), normal criteria
    index_t existing = 0;                    // an existing node, normal criteria
    index_t existing_relaxed = 0;            // an existing node, relaxed criteria
    std::array<index_t, 8> try_node{};       // try_node[k-1]: the k-th try node (relaxed)
    index_t moved_try_nodes = 0;             // of those, moved off the faces (candidates.hpp)
    index_t wedge_fronts = 0;                // fronts whose ideal apex opens a wedge (wedge.hpp)
    index_t lowered = 0;                     // fronts whose ideal apex was lowered (apart_factor)
    index_t shared_triangles = 0;            // pyramid triangles that are a face of two pyramids
    index_t covered_boundary_triangles = 0;  // boundary triangles that became a pyramid face
    // Events over the whole run (a front rejected in two rounds counts twice).
    index_t rejected = 0;          // fronts the normal pass could not serve
    index_t rejected_relaxed = 0;  // fronts the relaxed pass could not serve either
    index_t drawback_rounds = 0;
    index_t drawback_deleted = 0;  // pyramids deleted by drawbacks
    // Conflict-free batches over all passes.
    index_t batches = 0;
    index_t batch_min = 0, batch_max = 0;
    double batch_mean = 0;
    // Candidate evaluations by verdict, indexed by Verdict.
    std::array<std::uint64_t, kVerdictCount> verdicts{};
};

struct PyramidResult {
    index_t first_pyramid = 0;  // the new pyramids are cells [first_pyramid, +fronts) of kind
                                // Pyramid; pyramid k sits on front quad k
    index_t first_apex = 0;     // the new apex nodes are points [first_apex, point_count())
    // 3 node ids per triangle, normal out of the tet region: the pyramid triangles that are a
    // face of one pyramid only. With the boundary triangles not listed below, the closed
    // boundary of the tet region.
    std::vector<index_t> free_triangles;
    // Indices into PyramidInput::boundary_triangles of the triangles that a pyramid face
    // now covers (an existing-node apex can make a pyramid face coincide with one); they no
    // longer bound the tet region.
    std::vector<index_t> covered_boundary_triangles;
    PyramidStats stats;
};

// What build_pyramids throws when well-formed fronts find no valid pyramid: the fronts, so that
// a caller can tell which rings lack room (the pipeline retries them thinner).
class PyramidRoomError : public Error {
public:
    PyramidRoomError(const std::string& finding, const std::string& advice, std::vector<index_t> fronts)
        : Error(finding + ": " + advice), finding(finding), fronts(std::move(fronts)) {}
    std::string finding;          // what failed and where, without the advice (a caller may give its own)
    std::vector<index_t> fronts;  // front quad indices, ascending
};

// Puts one pyramid on every front quad: appends the apexes to mesh's points and the
// pyramids (region in.region) to its pyramid cells. Parallel with oneTBB; the appended data
// is identical for every thread count. Throws tubemesh::Error, leaving the mesh unchanged,
// when the input is malformed, and PyramidRoomError when some front finds no valid pyramid
// after opt.max_drawback_rounds drawbacks.
PyramidResult build_pyramids(HybridMesh& mesh, const PyramidInput& in, const PyramidOptions& opt = {});

}  // namespace tubemesh
