#include "geom/import/step_write.hpp"

#include <Interface_Static.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <StepData_Protocol.hxx>
#include <StepData_StepModel.hxx>
#include <StepData_StepWriter.hxx>
#include <StepRepr_Representation.hxx>
#include <StepRepr_RepresentationItem.hxx>
#include <StepShape_ShapeDefinitionRepresentation.hxx>
#include <StepShape_SolidModel.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TransferBRep.hxx>
#include <TransferBRep_ShapeMapper.hxx>
#include <Transfer_FinderProcess.hxx>
#include <XSControl_TransferWriter.hxx>
#include <XSControl_WorkSession.hxx>

#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/io/atomic_file.hpp"
#include "geom/model/face_names.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/import/occt_messages.hpp"
#include "geom/import/step_write_occt.hpp"
#include "geom/import/xstep_state.hpp"
#include "geom/model/scale_factor_occt.hpp"

namespace tubemesh::geom {

namespace {

struct StepUnit {
    std::string_view name;      // as ImportReport spells it
    const char* keyword;        // value of the write.step.unit parameter
    double millimetres;         // the unit's length in millimetres
};

// The units write.step.unit knows (UnitsMethods_LengthUnit), under the names import reports.
constexpr StepUnit kStepUnits[] = {
    {"millimetre", "MM", 1.0},       {"metre", "M", 1000.0},       {"centimetre", "CM", 10.0},
    {"kilometre", "KM", 1.0e6},      {"micron", "UM", 1.0e-3},     {"inch", "INCH", 25.4},
    {"foot", "FT", 304.8},           {"mile", "MI", 1609344.0},    {"mil", "MIL", 0.0254},
    {"microinch", "UIN", 2.54e-5},
};

const StepUnit& step_unit(const std::string& name) {
    for (const StepUnit& u : kStepUnits)
        if (u.name == name) return u;
    return kStepUnits[0];
}

}  // namespace

namespace {

// The name of the representation items each shape became: a solid of a compound is written
// as a shape definition whose representation holds its MANIFOLD_SOLID_BREP.
void name_items(STEPControl_Writer& writer, const TopoDS_Shape& root, std::span<const NamedShape> names) {
    const Handle(Transfer_FinderProcess) process = writer.WS()->TransferWriter()->FinderProcess();
    for (const auto& [shape, name] : names) {
        // A lone solid written as the root: the writer maps it to its product, not to the solid's
        // item, so name the model's one solid item directly.
        if (shape.IsSame(root) && root.ShapeType() == TopAbs_SOLID) {
            const Handle(StepData_StepModel) model = writer.Model();
            for (int i = 1; i <= model->NbEntities(); ++i)
                if (const auto solid = Handle(StepShape_SolidModel)::DownCast(model->Value(i)); !solid.IsNull())
                    solid->SetName(new TCollection_HAsciiString(name.c_str()));
            continue;
        }
        const Handle(TransferBRep_ShapeMapper) mapper = TransferBRep::ShapeMapper(process, shape);
        const Handle(Standard_Transient) found = process->FindTransient(mapper);
        const Handle(TCollection_HAsciiString) text = new TCollection_HAsciiString(name.c_str());
        if (const auto item = Handle(StepRepr_RepresentationItem)::DownCast(found); !item.IsNull()) {
            item->SetName(text);
        } else if (const auto sdr = Handle(StepShape_ShapeDefinitionRepresentation)::DownCast(found); !sdr.IsNull()) {
            const Handle(StepRepr_Representation) rep = sdr->UsedRepresentation();
            for (int i = 1; !rep.IsNull() && i <= rep->NbItems(); ++i)
                if (rep->ItemsValue(i)->IsKind(STANDARD_TYPE(StepShape_SolidModel))) rep->ItemsValue(i)->SetName(text);
        }
    }
}

}  // namespace

void write_step_shape(const TopoDS_Shape& shape, const std::filesystem::path& path, const std::string& length_unit,
                      std::span<const NamedShape> names) {
    silence_occt_output();
    const StepUnit& unit = step_unit(length_unit);
    // The text is made in memory and written by io::AtomicFile: OpenCASCADE's own file writing
    // tells only that it failed, not why (a full disk, a missing folder).
    std::ostringstream text;
    try {
        const XstepSession session;
        STEPControl_Writer writer;
        Interface_Static::SetCVal("write.step.unit", unit.keyword);
        struct RestoreDefaultUnit {
            ~RestoreDefaultUnit() { Interface_Static::SetCVal("write.step.unit", "MM"); }
        } restore;
        // Local and write units equal: the writer labels the coordinates with the unit and does
        // not scale them (OCCT converts between the two when they differ).
        writer.Model()->SetLocalLengthUnit(unit.millimetres);
        writer.Model()->SetWriteLengthUnit(unit.millimetres);
        if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone)
            throw Error("cannot write " + path.string() + ": OpenCASCADE could not translate the shape to STEP");
        name_items(writer, shape, names);
        // What STEPControl_Writer::Write does, to a stream (StepSelect_WorkLibrary::WriteFile).
        const Handle(StepData_Protocol) protocol = Handle(StepData_Protocol)::DownCast(writer.WS()->Protocol());
        if (protocol.IsNull()) throw Error("cannot write " + path.string() + ": OpenCASCADE has no STEP protocol");
        StepData_StepWriter step(writer.Model());
        step.SendModel(protocol);
        if (!step.Print(text) || !text)
            throw Error("cannot write " + path.string() + ": OpenCASCADE could not print the STEP text");
    } catch (const Standard_Failure& e) {
        throw Error("cannot write " + path.string() + ": OpenCASCADE failed with \"" + e.GetMessageString() + "\"");
    }
    io::AtomicFile file(path);
    file.write(text.view());
    file.commit();
}

void write_step(const Model& model, const std::filesystem::path& path) {
    const std::string& name = model.report().name;
    // Back at the source's scale (a scaled model's tolerances are reset on the way).
    const TopoDS_Shape solid = scaled_to_working(solid_of(model), -model.scale_exponent());
    std::vector<NamedShape> named;
    if (!name.empty()) named.emplace_back(solid, name);
    // The scaled copy keeps the faces' order, so face id i is the i-th face of either.
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(solid, TopAbs_FACE, faces);
    const std::vector<std::string> face_name = face_names(model);
    for (int id = 1; id <= faces.Extent() && id <= static_cast<int>(face_name.size()); ++id)
        if (!face_name[static_cast<std::size_t>(id - 1)].empty())
            named.emplace_back(faces(id), face_name[static_cast<std::size_t>(id - 1)]);
    write_step_shape(solid, path, model.report().length_unit, named);
}

}  // namespace tubemesh::geom
