#include "geom/import/cad_readers.hpp"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <Precision.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <STEPConstruct_UnitContext.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <StepData_GlobalFactors.hxx>
#include <StepData_StepModel.hxx>
#include <StepGeom_GeomRepContextAndGlobUnitAssCtxAndGlobUncertaintyAssCtx.hxx>
#include <StepGeom_GeometricRepresentationContextAndGlobalUnitAssignedContext.hxx>
#include <StepRepr_GlobalUnitAssignedContext.hxx>
#include <StepShape_Face.hxx>
#include <StepShape_SolidModel.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TransferBRep.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

#include <algorithm>
#include <cctype>
#include <fstream>

#include "engine/core/types.hpp"
#include "engine/io/file_bytes.hpp"
#include "geom/import/occt_messages.hpp"
#include "geom/import/xstep_state.hpp"
#include "geom/model/scale_factor.hpp"
#include "geom/model/scale_factor_occt.hpp"

namespace tubemesh::geom {

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

// IGES global section, parameter 14: the unit flag (IGES 5.3, section 2.2.4.3).
std::string iges_unit_name(int flag, const std::string& declared_name) {
    switch (flag) {
        case 1: return "inch";
        case 2: return "millimetre";
        case 4: return "foot";
        case 5: return "mile";
        case 6: return "metre";
        case 7: return "kilometre";
        case 8: return "mil";
        case 9: return "micron";
        case 10: return "centimetre";
        case 11: return "microinch";
        default: return declared_name.empty() ? "unknown (unit flag " + std::to_string(flag) + ")" : lower(declared_name);
    }
}

// The system length unit that makes the STEP reader's scale factor exactly 1 for the file's
// first unit context, or 0 when the file declares no length unit. The reader scales by
// c / L, where L is the system unit it is given and c what STEPConstruct_UnitContext computes
// for a cascade unit of 1; ComputeFactors divides by the current cascade unit, so c is its
// result times that unit. Matching the reader's own arithmetic, rather than converting unit
// names, keeps the file's numbers whatever convention c follows (OCCT 7.6 gives millimetres
// for SI units but metres for conversion-based ones such as INCH).
double step_reader_length_factor(const Handle(StepData_StepModel)& model) {
    for (int i = 1; i <= model->NbEntities(); ++i) {
        const Handle(Standard_Transient)& entity = model->Value(i);
        Handle(StepRepr_GlobalUnitAssignedContext) units;
        if (auto c = Handle(StepGeom_GeometricRepresentationContextAndGlobalUnitAssignedContext)::DownCast(entity))
            units = c->GlobalUnitAssignedContext();
        else if (auto c2 = Handle(StepGeom_GeomRepContextAndGlobUnitAssCtxAndGlobUncertaintyAssCtx)::DownCast(entity))
            units = c2->GlobalUnitAssignedContext();
        if (units.IsNull()) continue;
        STEPConstruct_UnitContext context;
        if (context.ComputeFactors(units) == 0 && context.LengthDone())
            return context.LengthFactor() * StepData_GlobalFactors::Intance().CascadeUnit();
    }
    return 0.0;
}

// `scale_exponent` k: the reader scales the coordinates by 10^-k (to the working scale).
// While a file is read at working scale, its healing uses OpenCASCADE's own precision: the
// file's uncertainty is a length in its unit (OCCT writes 1e-7 whatever the size), which the
// scaling would otherwise carry into the working space. Put back at the end of the read.
class WorkingPrecision {
public:
    explicit WorkingPrecision(int scale_exponent) : active_(scale_exponent != 0) {
        if (!active_) return;
        mode_ = Interface_Static::IVal("read.precision.mode");
        value_ = Interface_Static::RVal("read.precision.val");
        Interface_Static::SetIVal("read.precision.mode", 1);  // 1: the value below, not the file's
        Interface_Static::SetRVal("read.precision.val", Precision::Confusion());
    }
    ~WorkingPrecision() {
        if (!active_) return;
        Interface_Static::SetIVal("read.precision.mode", mode_);
        Interface_Static::SetRVal("read.precision.val", value_);
    }
    WorkingPrecision(const WorkingPrecision&) = delete;
    WorkingPrecision& operator=(const WorkingPrecision&) = delete;

private:
    bool active_;
    int mode_ = 0;
    double value_ = 0;
};

CadFile read_step(const std::filesystem::path& path, int scale_exponent) {
    const XstepSession session;
    const WorkingPrecision precision(scale_exponent);
    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
        throw Error(quoted(path) + " is not a readable STEP file: OpenCASCADE's STEP reader rejected it "
                    "(check that it is ISO 10303-21 text and not truncated)");
    CadFile out;
    TColStd_SequenceOfAsciiString lengths, angles, solid_angles;
    reader.FileUnits(lengths, angles, solid_angles);
    if (lengths.IsEmpty()) {
        out.length_unit = "millimetre";
        out.notes.push_back("the file declares no length unit; coordinates are taken as they are (STEP's default is millimetre)");
    } else {
        out.length_unit = lower(lengths.First().ToCString());
        if (lengths.Length() > 1) {
            std::string all;
            for (int i = 1; i <= lengths.Length(); ++i) all += (i > 1 ? ", " : "") + lower(lengths(i).ToCString());
            out.notes.push_back("the file uses several length units (" + all + "); parts in other units were converted to " +
                                out.length_unit);
        }
    }
    if (const double factor = step_reader_length_factor(reader.StepModel()); factor > 0)
        reader.SetSystemLengthUnit(from_working(factor, scale_exponent));
    else if (scale_exponent != 0)
        return {};  // no unit to scale through: read_cad_file scales the shape itself
    reader.TransferRoots();
    if (reader.NbShapes() == 0)
        throw Error(quoted(path) + " was read as STEP but holds no shape OpenCASCADE can convert (no solid, shell or face)");
    out.shape = reader.OneShape();
    // Named solids: each named MANIFOLD_SOLID_BREP and the shape it became.
    const Handle(Transfer_TransientProcess) process = reader.WS()->TransferReader()->TransientProcess();
    const Handle(StepData_StepModel) model = reader.StepModel();
    for (int i = 1; i <= model->NbEntities(); ++i) {
        const auto item = Handle(StepShape_SolidModel)::DownCast(model->Value(i));
        if (item.IsNull() || item->Name().IsNull() || item->Name()->Length() == 0) continue;
        const TopoDS_Shape shape = TransferBRep::ShapeResult(process, item);
        if (!shape.IsNull()) out.names.emplace_back(shape, item->Name()->ToCString());
    }
    // Named faces: each named face item (ADVANCED_FACE, ...) and the face it became. Exporters
    // that name no face write '' or 'NONE'.
    for (int i = 1; i <= model->NbEntities(); ++i) {
        const auto item = Handle(StepShape_Face)::DownCast(model->Value(i));
        if (item.IsNull() || item->Name().IsNull() || item->Name()->Length() == 0) continue;
        const std::string name = item->Name()->ToCString();
        if (lower(name) == "none") continue;
        const TopoDS_Shape shape = TransferBRep::ShapeResult(process, item);
        if (!shape.IsNull()) out.face_names.emplace_back(shape, name);
    }
    return out;
}

CadFile read_iges(const std::filesystem::path& path, int scale_exponent) {
    const WorkingPrecision precision(scale_exponent);
    IGESControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
        throw Error(quoted(path) + " is not a readable IGES file: OpenCASCADE's IGES reader rejected it "
                    "(check that it is IGES with 80-column records and not truncated)");
    IGESData_GlobalSection& header = reader.IGESModel()->ChangeGlobalSection();
    CadFile out;
    const Handle(TCollection_HAsciiString) name = header.UnitName();
    out.length_unit = iges_unit_name(header.UnitFlag(), name.IsNull() ? std::string() : name->ToCString());
    // The reader scales by UnitValue / CascadeUnit: making them equal keeps file coordinates.
    header.SetCascadeUnit(from_working(header.UnitValue(), scale_exponent));
    reader.TransferRoots();
    if (reader.NbShapes() == 0)
        throw Error(quoted(path) + " was read as IGES but holds no shape OpenCASCADE can convert (no solid, shell or face)");
    out.shape = reader.OneShape();
    return out;
}

CadFile read_brep(const std::filesystem::path& path) {
    CadFile out;
    BRep_Builder builder;
    if (!BRepTools::Read(out.shape, path.c_str(), builder) || out.shape.IsNull())
        throw Error(quoted(path) + " is not a readable BREP file: OpenCASCADE could not parse it "
                    "(check that it was written by BRepTools::Write or a tool based on it)");
    out.length_unit = "model units";
    out.notes.push_back("BREP files carry no unit: coordinates are used as they are");
    return out;
}

bool has_extension(const std::string& ext, std::initializer_list<const char*> list) {
    return std::any_of(list.begin(), list.end(), [&](const char* e) { return ext == e; });
}

}  // namespace

const char* format_name(CadFormat format) {
    switch (format) {
        case CadFormat::Step: return "STEP";
        case CadFormat::Iges: return "IGES";
        case CadFormat::Brep: return "BREP";
    }
    return "?";
}

CadFormat detect_cad_format(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        throw Error("cannot open " + quoted(path) + ": no such file");
    io::require_regular_file(path);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot open " + quoted(path) + ": permission denied or unreadable");

    const std::string ext = lower(path.extension().string());
    if (has_extension(ext, {".step", ".stp", ".p21"})) return CadFormat::Step;
    if (has_extension(ext, {".iges", ".igs"})) return CadFormat::Iges;
    if (has_extension(ext, {".brep", ".brp"})) return CadFormat::Brep;

    // Unknown extension: look at the first line, which each format fixes.
    std::string head(512, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    if (head.rfind("ISO-10303-21", 0) == 0) return CadFormat::Step;
    if (head.find("CASCADE Topology") != std::string::npos || head.find("DBRep_DrawableShape") != std::string::npos)
        return CadFormat::Brep;
    if (head.size() >= 73 && head[72] == 'S') return CadFormat::Iges;  // start section flag in column 73
    throw Error(quoted(path) + " is not a CAD file tubemesh can read: expected STEP (.step/.stp), IGES (.iges/.igs) "
                "or BREP (.brep)");
}

namespace {

CadFile read_at_scale(const std::filesystem::path& path, CadFormat format, int scale_exponent) {
    switch (format) {
        case CadFormat::Step: return read_step(path, scale_exponent);
        case CadFormat::Iges: return read_iges(path, scale_exponent);
        case CadFormat::Brep: return read_brep(path);
    }
    throw Error("cannot read " + quoted(path) + ": unknown format");
}

}  // namespace

CadFile read_cad_file(const std::filesystem::path& path, CadFormat format) {
    silence_occt_output();
    try {
        CadFile file = read_at_scale(path, format, 0);
        // A file far from the working scale is read again with the readers' own unit
        // conversion scaling it, so their healing (absolute tolerances) already sees the
        // working-scale solid; a BREP file, or a STEP file without units, is scaled after.
        const int k = working_scale_exponent(file.shape);
        if (k == 0) return file;
        CadFile scaled = format == CadFormat::Brep ? CadFile{} : read_at_scale(path, format, k);
        if (scaled.shape.IsNull()) {
            scaled = std::move(file);
            scaled.shape = scaled_to_working(scaled.shape, k);
            scaled.names.clear();  // the names point at the unscaled solids and faces
            scaled.face_names.clear();
        }
        scaled.scale_exponent = k;
        return scaled;
    } catch (const Standard_Failure& e) {
        throw Error("cannot read " + quoted(path) + " as " + format_name(format) + ": OpenCASCADE failed with \"" +
                    e.GetMessageString() + "\"");
    }
    throw Error("cannot read " + quoted(path) + ": unknown format");
}

}  // namespace tubemesh::geom
