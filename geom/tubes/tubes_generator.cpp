#include "geom/tubes/tubes_generator.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace tubemesh::geom {
namespace {

// Parameter steps per piece in the arc length table: at least this many, and this many per
// polynomial span of a B-spline isoline, so 8-point Gauss-Legendre on each step is exact to
// rounding and Newton from the table's linear guess needs a step or two.
constexpr int kTableSteps = 64;
constexpr int kStepsPerSpan = 8;

constexpr std::array<double, 8> kGaussX{-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                                        -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                                        0.7966664774136267,  0.9602898564975363};
constexpr std::array<double, 8> kGaussW{0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                                        0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

double speed(const GeomAdaptor_Curve& c, double t) {
    gp_Pnt p;
    gp_Vec d;
    c.D1(t, p, d);
    return d.Magnitude();
}

// Arc length between parameters a and b (signed: negative when b < a).
double arc_between(const GeomAdaptor_Curve& c, double a, double b) {
    const double half = (b - a) / 2, mid = (a + b) / 2;
    double sum = 0;
    for (int i = 0; i < 8; ++i) sum += kGaussW[i] * speed(c, mid + half * kGaussX[i]);
    return sum * half;
}

}  // namespace

Generator::Generator(std::vector<GeneratorPiece> pieces, LoopPoint start, LoopPoint end)
    : pieces_(std::move(pieces)), start_(start), end_(end) {
    for (GeneratorPiece& piece : pieces_) {
        Table table;
        table.curve = new GeomAdaptor_Curve(piece.iso, std::min(piece.from, piece.to), std::max(piece.from, piece.to));
        table.params.push_back(piece.from);
        table.arc.push_back(0);
        const int steps = std::max(kTableSteps, kStepsPerSpan * table.curve->NbIntervals(GeomAbs_C2));
        for (int i = 1; i <= steps; ++i) {
            const double t = piece.from + (piece.to - piece.from) * i / steps;
            table.arc.push_back(table.arc.back() + std::abs(arc_between(*table.curve, table.params.back(), t)));
            table.params.push_back(t);
        }
        piece.length = table.arc.back();
        starts_.push_back(length_);
        length_ += piece.length;
        tables_.push_back(std::move(table));
    }
}

Generator Generator::independent_copy() const {
    Generator copy = *this;
    for (std::size_t k = 0; k < pieces_.size(); ++k) {
        copy.pieces_[k].iso = Handle(Geom_Curve)::DownCast(pieces_[k].iso->Copy());
        const GeomAdaptor_Curve& c = *tables_[k].curve;
        copy.tables_[k].curve = new GeomAdaptor_Curve(copy.pieces_[k].iso, c.FirstParameter(), c.LastParameter());
    }
    return copy;
}

double Generator::param_at(int k, double ds) const {
    const Table& table = tables_[k];
    const auto it = std::upper_bound(table.arc.begin(), table.arc.end(), ds);
    const std::size_t i = std::clamp<std::size_t>(it - table.arc.begin(), 1, table.arc.size() - 1);
    const double a = table.params[i - 1], b = table.params[i];
    const double s0 = table.arc[i - 1], s1 = table.arc[i];
    double t = a + (b - a) * (s1 > s0 ? (ds - s0) / (s1 - s0) : 0.0);
    const double dir = b >= a ? 1.0 : -1.0;
    // Newton on s(t) = s0 + |arc from a to t|; the speed is its derivative along the walk.
    for (int it_ = 0; it_ < 8; ++it_) {
        const double f = s0 + dir * arc_between(*table.curve, a, t) - ds;
        const double v = speed(*table.curve, t);
        if (!(v > 0)) break;
        const double step = dir * f / v;
        t -= step;
        if (std::abs(step) <= 1e-15 * (std::abs(t) + std::abs(b - a))) break;
    }
    return t;
}

GeneratorPoint Generator::eval(int k, double param) const {
    const GeneratorPiece& piece = pieces_[k];
    gp_Pnt p;
    gp_Vec c1, c2;
    tables_[k].curve->D2(param, p, c1, c2);
    const double v = c1.Magnitude();
    const gp_Vec unit = c1 / v * (piece.to >= piece.from ? 1.0 : -1.0);
    // Curvature vector: the part of C'' normal to the tangent, over |C'|^2. It does not depend
    // on the direction of travel.
    const gp_Vec normal_part = c2 - unit * c2.Dot(unit);
    return {p, unit * length_, normal_part * (length_ * length_ / (v * v))};
}

GeneratorPoint Generator::at(double sigma) const {
    const double s = std::clamp(sigma, 0.0, 1.0) * length_;
    auto it = std::upper_bound(starts_.begin(), starts_.end(), s);
    const int k = static_cast<int>(std::max<std::ptrdiff_t>(0, (it - starts_.begin()) - 1));
    return eval(k, param_at(k, std::clamp(s - starts_[k], 0.0, pieces_[k].length)));
}

double Generator::max_kink() const {
    double worst = 0;
    for (std::size_t k = 1; k < pieces_.size(); ++k) {
        const gp_Vec a = eval(static_cast<int>(k - 1), pieces_[k - 1].to).d1;
        const gp_Vec b = eval(static_cast<int>(k), pieces_[k].from).d1;
        if (a.Magnitude() > 0 && b.Magnitude() > 0) worst = std::max(worst, a.Angle(b));
    }
    return worst;
}

}  // namespace tubemesh::geom
