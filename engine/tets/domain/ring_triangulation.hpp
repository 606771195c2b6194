#pragma once
// Klincsek's dynamic programme over the triangulations of a polygon: the one search behind
// both edge removals of the tet step, boundary recovery's (recovery_flips.cpp) and the
// optimisation's (tet_flips.cpp). Removing edge ab whose shell has the ring of points
// p_0 .. p_{n-1} puts two tets on each triangle (p_i, p_k, p_j) of a triangulation of the ring
// polygon, one towards a and one towards b; the best triangulation is the one whose worst
// triangle (the worse of its two tets) is best (Shewchuk, "Two discrete optimization
// algorithms for the topological improvement of tetrahedral meshes"). The callers differ only
// in how a triangle is scored (which measure, which tets are valid) and which chords may be
// used, so those come in as callables.
#include <algorithm>
#include <array>
#include <limits>

namespace tubemesh::tets {

// A triangle of the ring as the programme sees it: `min`, the smaller of its two tets'
// scores, is its score; `first` and `second` are the two, for callers that also sum them.
struct RingTriangle {
    double min, first, second;  // no initialisers: scored millions of times per mesh
};

// N: the largest ring. The tables live inside the object, uninitialised: planning runs
// hundreds of thousands of times per mesh, and solve() writes every entry it later reads.
template <int N>
class RingTriangulation {
public:
    // Searches the triangulations of the n-gon (3 <= n <= N) whose every triangle beats
    // `floor` for one whose worst triangle is best; true when there is one (value() > floor).
    //   score(i, k, j, beat) -> RingTriangle for triangle (p_i, p_k, p_j), i < k < j. When it
    //     knows early that the triangle's min cannot exceed `beat`, it may return any min <=
    //     beat (the triangle is then not used): the search's result is the same.
    //   chord(i, j) -> false keeps every triangle with side p_i p_j out (asked for j >= i + 2;
    //     the polygon's own sides p_i p_{i+1} and p_0 p_{n-1} are always usable).
    // Ties keep the first split k in increasing order, so the result is deterministic.
    template <class Score, class Chord>
    bool solve(int n, double floor, Score&& score, Chord&& chord) {
        n_ = n;
        for (int i = 0; i + 1 < n; ++i) best_[i][i + 1] = std::numeric_limits<double>::infinity();
        for (int gap = 2; gap < n; ++gap) {
            for (int i = 0; i + gap < n; ++i) {
                const int j = i + gap;
                double q_best = floor;
                int k_best = i + 1;
                if (gap == n - 1 || chord(i, j)) {
                    for (int k = i + 1; k < j; ++k) {
                        const double sub = std::min(best_[i][k], best_[k][j]);
                        if (sub <= q_best) continue;
                        const RingTriangle t = score(i, k, j, q_best);
                        const double q = std::min(sub, t.min);
                        if (q > q_best) {
                            q_best = q;
                            k_best = k;
                            chosen_[i][j] = {t.first, t.second};
                        }
                    }
                }
                best_[i][j] = q_best;
                split_[i][j] = k_best;
            }
        }
        return best_[0][n - 1] > floor;
    }

    // The worst triangle's score of the triangulation found (floor when there is none).
    double value() const { return best_[0][n_ - 1]; }

    // visit(i, k, j, first, second) for each triangle of the triangulation found (only after
    // solve() returned true): depth first from the side p_0 p_{n-1}, the (k, j) part of each
    // split before its (i, k) part.
    template <class Visit>
    void for_each_triangle(Visit&& visit) const {
        std::array<std::array<int, 2>, N> stack{};
        int top = 0;
        stack[top++] = {0, n_ - 1};
        while (top > 0) {
            const auto [i, j] = stack[--top];
            if (j - i < 2) continue;
            const int k = split_[i][j];
            visit(i, k, j, chosen_[i][j][0], chosen_[i][j][1]);
            stack[top++] = {i, k};
            stack[top++] = {k, j};
        }
    }

private:
    int n_ = 0;
    std::array<std::array<double, N>, N> best_;  // best_[i][j]: sub-polygon p_i .. p_j
    std::array<std::array<int, N>, N> split_;
    std::array<std::array<std::array<double, 2>, N>, N> chosen_;  // the chosen split's two tets
};

}  // namespace tubemesh::tets
