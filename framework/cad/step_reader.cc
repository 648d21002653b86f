#include "framework/cad/step_reader.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include <APIHeaderSection_MakeHeader.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <StepData_StepModel.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TDF_Label.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TransferBRep.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDimTolObjects_DatumObject.hxx>
#include <XCAFDimTolObjects_DimensionObject.hxx>
#include <XCAFDimTolObjects_GeomToleranceObject.hxx>
#include <XCAFDoc_Datum.hxx>
#include <XCAFDoc_DimTolTool.hxx>
#include <XCAFDoc_Dimension.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_GeomTolerance.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace fitfeel::cad {
namespace {

// The reader gives lengths in millimetres (its default xstep.cascade.unit).
constexpr double kMetresPerReaderUnit = 1e-3;

std::array<double, 3> Metres(const gp_XYZ& p) {
  return {p.X() * kMetresPerReaderUnit, p.Y() * kMetresPerReaderUnit, p.Z() * kMetresPerReaderUnit};
}
std::array<double, 3> Unit(const gp_Dir& d) { return {d.X(), d.Y(), d.Z()}; }

// Each face's triangles with the face's location applied, turned round where the face is
// reversed so that every triangle faces out of the material.
void Tessellate(const TopoDS_Shape& shape, CadPart* part) {
  BRepMesh_IncrementalMesh mesher(shape, kMeshLinearDeflection / kMetresPerReaderUnit,
                                  Standard_False, kMeshAngularDeflection, Standard_False);
  std::size_t triangles = 0;
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
    TopLoc_Location location;
    const Handle(Poly_Triangulation) t =
        BRep_Tool::Triangulation(TopoDS::Face(it.Current()), location);
    if (!t.IsNull()) triangles += static_cast<std::size_t>(t->NbTriangles());
  }
  if (triangles > kMaxMeshTriangles) {
    part->mesh_note = "its tessellation has " + std::to_string(triangles) +
                      " triangles, above the " + std::to_string(kMaxMeshTriangles) +
                      " the viewer takes";
    return;
  }
  part->mesh.reserve(9 * triangles);
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
    const TopoDS_Face& face = TopoDS::Face(it.Current());
    TopLoc_Location location;
    const Handle(Poly_Triangulation) t = BRep_Tool::Triangulation(face, location);
    if (t.IsNull()) continue;
    const gp_Trsf move = location.Transformation();
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (Standard_Integer i = 1; i <= t->NbTriangles(); ++i) {
      Standard_Integer n[3];
      t->Triangle(i).Get(n[0], n[1], n[2]);
      if (reversed) std::swap(n[1], n[2]);
      for (const Standard_Integer k : n) {
        const std::array<double, 3> p = Metres(t->Node(k).Transformed(move).XYZ());
        for (const double c : p) part->mesh.push_back(static_cast<float>(c));
      }
    }
  }
  if (part->mesh.empty()) part->mesh_note = "the mesher gave its shape no triangles";
}

std::string Name(const TDF_Label& label) {
  Handle(TDataStd_Name) name;
  if (!label.FindAttribute(TDataStd_Name::GetID(), name)) return "";
  return TCollection_AsciiString(name->Get()).ToCString();
}

class Reader {
 public:
  // The faces' entity numbers are looked up once: the transfer reader's own lookup
  // (EntityFromShapeResult) passes over every mapped entity per face, which makes reading an
  // assembly quadratic in its faces.
  explicit Reader(STEPCAFControl_Reader& reader)
      : reader_(reader), model_(reader.ChangeReader().StepModel()) {
    const Handle(Transfer_TransientProcess) process =
        reader_.ChangeReader().WS()->TransferReader()->TransientProcess();
    if (process.IsNull()) return;
    for (int i = 1; i <= process->NbMapped(); ++i) {
      const TopoDS_Shape result = TransferBRep::ShapeResult(process->MapItem(i));
      if (result.IsNull() || result.ShapeType() != TopAbs_FACE) continue;
      const int entity = model_->IdentLabel(process->Mapped(i));
      if (!same_.IsBound(result)) same_.Bind(result, entity);
      by_shape_.emplace(result.TShape().get(), entity);
    }
  }

  // The STEP entity number of the face the reader made `face` from (the same face and place
  // first, then the same face anywhere); 0 when it kept none.
  int Entity(const TopoDS_Shape& face) const {
    if (const int* entity = same_.Seek(face)) return *entity;
    const auto found = by_shape_.find(face.TShape().get());
    return found == by_shape_.end() ? 0 : found->second;
  }

  CadFace Face(const TopoDS_Face& original, const TopLoc_Location& placement) const {
    CadFace out;
    out.entity = Entity(original);
    const TopoDS_Face face = TopoDS::Face(original.Moved(placement));
    BRepAdaptor_Surface surface(face);
    gp_Pnt origin;
    gp_Dir axis(0, 0, 1);
    switch (surface.GetType()) {
      case GeomAbs_Plane:
        out.kind = SurfaceKind::kPlane;
        origin = surface.Plane().Location();
        axis = surface.Plane().Axis().Direction();
        break;
      case GeomAbs_Cylinder:
        out.kind = SurfaceKind::kCylinder;
        origin = surface.Cylinder().Location();
        axis = surface.Cylinder().Axis().Direction();
        out.radius = surface.Cylinder().Radius() * kMetresPerReaderUnit;
        break;
      case GeomAbs_Cone:
        out.kind = SurfaceKind::kCone;
        origin = surface.Cone().Location();
        axis = surface.Cone().Axis().Direction();
        out.radius = surface.Cone().RefRadius() * kMetresPerReaderUnit;
        out.semi_angle = surface.Cone().SemiAngle();
        break;
      case GeomAbs_Sphere:
        out.kind = SurfaceKind::kSphere;
        origin = surface.Sphere().Location();
        // A band of a sphere is bounded by circles of latitude about its own axis.
        axis = surface.Sphere().Position().Direction();
        out.radius = surface.Sphere().Radius() * kMetresPerReaderUnit;
        break;
      case GeomAbs_BSplineSurface:
      case GeomAbs_BezierSurface:
        out.kind = SurfaceKind::kBSpline;
        out.surface_type = surface.GetType() == GeomAbs_BSplineSurface ? "B-spline" : "Bezier";
        break;
      default:
        out.kind = SurfaceKind::kOther;
        out.surface_type = "surface type " + std::to_string(static_cast<int>(surface.GetType()));
        break;
    }
    out.origin = Metres(origin.XYZ());
    out.axis = Unit(axis);
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    BRepGProp_Face normals(face);
    bool first = true;
    constexpr int kGrid = 5;
    for (int i = 0; i < kGrid; ++i) {
      for (int j = 0; j < kGrid; ++j) {
        const double u = u0 + (u1 - u0) * (i + 0.5) / kGrid;
        const double v = v0 + (v1 - v0) * (j + 0.5) / kGrid;
        gp_Pnt p;
        gp_Vec normal;
        normals.Normal(u, v, p, normal);
        const gp_Vec from(origin, p);
        const double along = from.Dot(gp_Vec(axis)) * kMetresPerReaderUnit;
        if (first || along < out.axial_min) out.axial_min = along;
        if (first || along > out.axial_max) out.axial_max = along;
        if (i == kGrid / 2 && j == kGrid / 2) {
          const gp_Vec radial = out.kind == SurfaceKind::kSphere
                                    ? from
                                    : from - gp_Vec(axis) * from.Dot(gp_Vec(axis));
          out.convex = normal.Dot(radial) > 0.0;
        }
        if (out.kind == SurfaceKind::kBSpline) out.samples.push_back(Metres(p.XYZ()));
        first = false;
      }
    }
    // The grid's rows sit half a step inside the face: its axial extent comes from its bounds.
    // v is the axial coordinate of a cylinder, the slant one of a cone (along the axis v cos of
    // the semi-angle) and the latitude of a sphere (along the axis R sin v).
    const double lo = std::min(v0, v1), hi = std::max(v0, v1);
    if (out.kind == SurfaceKind::kCylinder) {
      out.axial_min = lo * kMetresPerReaderUnit;
      out.axial_max = hi * kMetresPerReaderUnit;
    } else if (out.kind == SurfaceKind::kCone) {
      const double c = std::cos(out.semi_angle) * kMetresPerReaderUnit;
      out.axial_min = lo * c;
      out.axial_max = hi * c;
    } else if (out.kind == SurfaceKind::kSphere) {
      out.axial_min = out.radius * std::sin(std::max(lo, -M_PI / 2));
      out.axial_max = out.radius * std::sin(std::min(hi, M_PI / 2));
    }
    return out;
  }

  void Walk(const Handle(XCAFDoc_ShapeTool) & shapes, const TDF_Label& label,
            const TopLoc_Location& placement, CadDocument& document) const {
    if (XCAFDoc_ShapeTool::IsAssembly(label)) {
      TDF_LabelSequence components;
      XCAFDoc_ShapeTool::GetComponents(label, components);
      for (const TDF_Label& component : components) {
        TDF_Label part;
        if (!XCAFDoc_ShapeTool::GetReferredShape(component, part)) continue;
        Walk(shapes, part, placement * XCAFDoc_ShapeTool::GetLocation(component), document);
      }
      return;
    }
    CadPart part;
    part.name = Name(label);
    const TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(label);
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
      part.faces.push_back(Face(TopoDS::Face(it.Current()), placement));
    }
    Tessellate(shape.Moved(placement), &part);
    document.parts.push_back(std::move(part));
  }

  std::vector<int> Faces(const Handle(XCAFDoc_DimTolTool) & tool, const TDF_Label& label) const {
    TDF_LabelSequence first, second;
    tool->GetRefShapeLabel(label, first, second);
    std::vector<int> out;
    for (const TDF_Label& face : first) {
      const TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(face);
      for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
        out.push_back(Entity(it.Current()));
      }
    }
    return out;
  }

  void Tolerances(const Handle(TDocStd_Document) & doc, CadDocument& document) const {
    const Handle(XCAFDoc_DimTolTool) tool = XCAFDoc_DocumentTool::DimTolTool(doc->Main());
    static const char* const kLetters[] = {"",  "A", "B",  "C", "CD", "D", "E",  "EF", "F", "FG",
                                           "G", "H", "JS", "J", "K",  "M", "N",  "P",  "R", "S",
                                           "T", "U", "V",  "X", "Y",  "Z", "ZA", "ZB", "ZC"};
    TDF_LabelSequence labels;
    tool->GetDimensionLabels(labels);
    for (const TDF_Label& label : labels) {
      Handle(XCAFDoc_Dimension) attribute;
      if (!label.FindAttribute(XCAFDoc_Dimension::GetID(), attribute)) continue;
      const Handle(XCAFDimTolObjects_DimensionObject) object = attribute->GetObject();
      if (object.IsNull()) continue;
      CadTolerance tolerance;
      const XCAFDimTolObjects_DimensionType type = object->GetType();
      tolerance.kind = type == XCAFDimTolObjects_DimensionType_Size_Diameter
                           ? ToleranceKind::kSize
                           : ToleranceKind::kOther;
      tolerance.type = "dimension type " + std::to_string(static_cast<int>(type));
      if (tolerance.kind == ToleranceKind::kSize) tolerance.type = "diameter";
      tolerance.faces = Faces(tool, label);
      tolerance.value = object->GetValue() * kMetresPerReaderUnit;
      if (object->IsDimWithRange()) {
        tolerance.has_range = true;
        tolerance.lower = object->GetLowerBound() * kMetresPerReaderUnit;
        tolerance.upper = object->GetUpperBound() * kMetresPerReaderUnit;
      } else if (object->IsDimWithPlusMinusTolerance()) {
        tolerance.has_plus_minus = true;
        tolerance.lower = object->GetLowerTolValue() * kMetresPerReaderUnit;
        tolerance.upper = object->GetUpperTolValue() * kMetresPerReaderUnit;
      }
      Standard_Boolean hole = false;
      XCAFDimTolObjects_DimensionFormVariance letter = XCAFDimTolObjects_DimensionFormVariance_None;
      XCAFDimTolObjects_DimensionGrade grade = XCAFDimTolObjects_DimensionGrade_IT01;
      if (object->IsDimWithClassOfTolerance() && object->GetClassOfTolerance(hole, letter, grade)) {
        const int index = static_cast<int>(letter);
        std::string code = index >= 0 && index < 29 ? kLetters[index] : "?";
        if (!hole) {
          for (char& c : code) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        }
        const int g = static_cast<int>(grade);
        code += g == 0 ? "01" : std::to_string(g - 1);
        tolerance.iso_class = code;
        tolerance.hole_class = hole;
      }
      document.tolerances.push_back(std::move(tolerance));
    }
    labels.Clear();
    tool->GetGeomToleranceLabels(labels);
    for (const TDF_Label& label : labels) {
      Handle(XCAFDoc_GeomTolerance) attribute;
      if (!label.FindAttribute(XCAFDoc_GeomTolerance::GetID(), attribute)) continue;
      const Handle(XCAFDimTolObjects_GeomToleranceObject) object = attribute->GetObject();
      if (object.IsNull()) continue;
      CadTolerance tolerance;
      switch (object->GetType()) {
        case XCAFDimTolObjects_GeomToleranceType_CircularityOrRoundness:
          tolerance.kind = ToleranceKind::kRoundness;
          break;
        case XCAFDimTolObjects_GeomToleranceType_Cylindricity:
          tolerance.kind = ToleranceKind::kCylindricity;
          break;
        case XCAFDimTolObjects_GeomToleranceType_Straightness:
          tolerance.kind = ToleranceKind::kStraightness;
          break;
        case XCAFDimTolObjects_GeomToleranceType_Flatness:
          tolerance.kind = ToleranceKind::kFlatness;
          break;
        default:
          tolerance.kind = ToleranceKind::kOther;
          break;
      }
      tolerance.type =
          tolerance.kind == ToleranceKind::kOther
              ? "geometric tolerance type " + std::to_string(static_cast<int>(object->GetType()))
              : ToleranceKindName(tolerance.kind);
      tolerance.faces = Faces(tool, label);
      tolerance.value = object->GetValue() * kMetresPerReaderUnit;
      document.tolerances.push_back(std::move(tolerance));
    }
    labels.Clear();
    tool->GetDatumLabels(labels);
    for (const TDF_Label& label : labels) {
      Handle(XCAFDoc_Datum) attribute;
      if (!label.FindAttribute(XCAFDoc_Datum::GetID(), attribute)) continue;
      const Handle(XCAFDimTolObjects_DatumObject) object = attribute->GetObject();
      if (object.IsNull() || object->GetName().IsNull()) continue;
      for (const int face : Faces(tool, label)) {
        for (CadPart& part : document.parts) {
          for (const CadFace& f : part.faces) {
            if (f.entity == face) {
              part.datums.push_back(std::string(object->GetName()->ToCString()) + " on #" +
                                    std::to_string(face));
            }
          }
        }
      }
    }
  }

 private:
  STEPCAFControl_Reader& reader_;
  Handle(StepData_StepModel) model_;
  TopTools_DataMapOfShapeInteger same_;
  std::unordered_map<const TopoDS_TShape*, int> by_shape_;
};

}  // namespace

CadDocument ReadStepHere(const std::filesystem::path& file) {
  STEPCAFControl_Reader reader;
  reader.SetNameMode(true);
  reader.SetGDTMode(true);
  reader.SetColorMode(false);
  reader.SetLayerMode(false);
  reader.SetPropsMode(false);
  const IFSelect_ReturnStatus status = reader.ReadFile(file.c_str());
  if (status != IFSelect_RetDone) {
    throw std::runtime_error("the STEP reader does not read it as a STEP file (status " +
                             std::to_string(static_cast<int>(status)) + ")");
  }
  CadDocument document;
  const Handle(StepData_StepModel) model = reader.ChangeReader().StepModel();
  APIHeaderSection_MakeHeader header(model);
  if (header.NbSchemaIdentifiers() > 0 && !header.SchemaIdentifiersValue(1).IsNull()) {
    document.schema = header.SchemaIdentifiersValue(1)->ToCString();
  }
  TColStd_SequenceOfAsciiString lengths, angles, solid_angles;
  reader.ChangeReader().FileUnits(lengths, angles, solid_angles);
  if (!lengths.IsEmpty()) document.length_unit = lengths.First().ToCString();
  Handle(TDocStd_Document) doc;
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
  if (!reader.Transfer(doc)) throw std::runtime_error("the STEP reader transferred no shape");
  const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  TDF_LabelSequence free_shapes;
  shapes->GetFreeShapes(free_shapes);
  const Reader walker(reader);
  for (const TDF_Label& label : free_shapes)
    walker.Walk(shapes, label, TopLoc_Location(), document);
  if (document.parts.empty()) throw std::runtime_error("the file holds no shape");
  walker.Tolerances(doc, document);
  return document;
}

}  // namespace fitfeel::cad
