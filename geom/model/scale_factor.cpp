#include "geom/model/scale_factor.hpp"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepLib.hxx>
#include <Bnd_Box.hxx>
#include <Precision.hxx>
#include <ShapeFix_ShapeTolerance.hxx>
#include <gp_Pnt.hxx>
#include <gp_Trsf.hxx>

#include <cmath>

#include "geom/model/scale_factor_occt.hpp"

namespace tubemesh::geom {

namespace {

double power_of_ten(int n) {  // exact for the exponents a double holds exactly (n <= 22)
    double p = 1;
    for (int i = 0; i < n; ++i) p *= 10;
    return p;
}

}  // namespace

int working_scale_exponent(double diagonal) {
    if (!(diagonal > 0) || !std::isfinite(diagonal)) return 0;
    return 3 * static_cast<int>(std::floor(std::log10(diagonal) / 3));
}

double to_working(double length, int k) { return k >= 0 ? length / power_of_ten(k) : length * power_of_ten(-k); }
double from_working(double length, int k) { return k >= 0 ? length * power_of_ten(k) : length / power_of_ten(-k); }

int working_scale_exponent(const TopoDS_Shape& shape) {
    Bnd_Box box;
    BRepBndLib::Add(shape, box, /*useTriangulation=*/false);
    if (box.IsVoid()) return 0;
    return working_scale_exponent(std::sqrt(box.SquareExtent()));
}

TopoDS_Shape scaled_to_working(const TopoDS_Shape& shape, int k) {
    if (k == 0) return shape;
    gp_Trsf scale;
    scale.SetScale(gp_Pnt(0, 0, 0), to_working(1.0, k));
    BRepBuilderAPI_Transform transform(shape, scale, /*copy=*/true);
    TopoDS_Shape scaled = transform.Shape();
    ShapeFix_ShapeTolerance().SetTolerance(scaled, Precision::Confusion());
    BRepLib::UpdateTolerances(scaled, /*verifyFaceTolerance=*/true);
    return scaled;
}

}  // namespace tubemesh::geom
