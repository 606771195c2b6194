#pragma once
// Valid solids whose run fails in a later phase, meshed again with what the user did not give
// (mesh_file.hpp runs the attempts). Only a failure the pipeline calls retryable
// (RetryableFailure) is retried, so a run that succeeds the first time is never changed.
//
//  * The pyramids find no room in front of some rings (Cause::PyramidRoom): with St automatic,
//    the rings of those tubes alone are made thinner, St x 0.7 per attempt, each at most
//    kSweepSteps times; the other rings keep the plan's St. A tube whose ring still finds no room
//    after those loses it: its wall is meshed with tets (geom/prepare.hpp), with a warning. With
//    St given, the run is refused naming that St and a thinner one to try.
//  * Boundary recovery gives up on a front that passed its checks (Cause::Recovery; seen on
//    long, nearly flat surface triangles along a hole's generator, where the flips and Steiner
//    points of engine/tets/recovery run out): the chordal tolerance is doubled, at most
//    kChordalSteps times. With the tolerance given, the same attempts look for one that works and
//    the run is refused naming it (the user asked for that tolerance; the mesh at another is not
//    what was asked for).
//
// Every attempt is deterministic, so the mesh of a retried run is too. No OpenCASCADE header here.
#include <optional>
#include <string>
#include <vector>

#include "engine/pipeline/pipeline.hpp"
#include "geom/prepare.hpp"

namespace tubemesh::geom {

class RunRetry {
public:
    // Thinner rings per attempt, and attempts per tube.
    static constexpr double kSweepFactor = 0.7;
    static constexpr int kSweepSteps = 4;
    // Coarser chordal tolerance per attempt, and attempts.
    static constexpr double kChordalFactor = 2.0;
    static constexpr int kChordalSteps = 3;

    explicit RunRetry(const MeshOptions& options);

    // The options of the next attempt: the user's, with this retry's St per tube and tolerance.
    PrepareOptions prepare_options() const;
    const MeshOptions& mesh_options() const { return options_; }

    // After a failed attempt on `prepared`: sets up the next one, or throws tubemesh::Error with
    // the failure's message and what to change.
    void after(const RetryableFailure& failure, const PreparedModel& prepared);
    // After an attempt that meshed: throws when it meshed only with a setting the user gave
    // changed (the message names the value that works).
    void accept() const;

    // What the user should be told about a retried run (empty when none was): warnings, and the
    // lines for the plan's report.
    std::vector<std::string> warnings() const;
    std::vector<std::string> report_lines() const;
    // Why tube t's ring (an index into the last attempt's tubes) is thinner than the plan's St;
    // empty when the retry did not thin it.
    std::string ring_reason(std::size_t t) const;

private:
    MeshOptions options_;     // the next attempt's
    bool sweep_given_ = false;
    bool global_fallback_ = false;  // the local ring gave way to the paper's one St
    double chordal_first_ = 0;  // the tolerance of the first attempt
    int chordal_steps_ = 0;
    std::optional<std::string> chordal_failure_;  // the first recovery failure's message
    double plan_sweep_ = 0;                        // the plan's St, once a tube was thinned
    std::vector<int> sweep_steps_;                 // per tube
    std::optional<std::string> room_failure_;      // the first pyramid failure's message
    std::vector<RingDrop> dropped_;                // tubes whose rings found no room at any St tried
};

}  // namespace tubemesh::geom
