// The CAD record of each B-rep face: its surface type and, for planes, cylinders and cones,
// the axis data a machining planner uses (approach directions, hole axes).
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <TopoDS.hxx>
#include <gp_Cone.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>

#include <cmath>
#include <cstdio>

#include "step/step_internal.h"

namespace gvm {

namespace step_internal {
namespace {

CadSurfaceType type_of(GeomAbs_SurfaceType t) {
  switch (t) {
    case GeomAbs_Plane: return CadSurfaceType::kPlane;
    case GeomAbs_Cylinder: return CadSurfaceType::kCylinder;
    case GeomAbs_Cone: return CadSurfaceType::kCone;
    case GeomAbs_Sphere: return CadSurfaceType::kSphere;
    case GeomAbs_Torus: return CadSurfaceType::kTorus;
    case GeomAbs_BezierSurface: return CadSurfaceType::kBezier;
    case GeomAbs_BSplineSurface: return CadSurfaceType::kBSpline;
    case GeomAbs_SurfaceOfRevolution: return CadSurfaceType::kRevolution;
    case GeomAbs_SurfaceOfExtrusion: return CadSurfaceType::kExtrusion;
    case GeomAbs_OffsetSurface: return CadSurfaceType::kOffset;
    default: return CadSurfaceType::kOther;
  }
}

std::array<double, 3> xyz(const gp_XYZ& v) { return {v.X(), v.Y(), v.Z()}; }

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

}  // namespace

std::vector<CadFace> describe_faces(const TopTools_IndexedMapOfShape& faces) {
  std::vector<CadFace> out(faces.Extent());
  for (int i = 1; i <= faces.Extent(); ++i) {
    const TopoDS_Face& face = TopoDS::Face(faces(i));
    CadFace& c = out[i - 1];
    c.index = uint32_t(i - 1);
    // BRepAdaptor_Surface applies the face location to the elementary surfaces it returns.
    BRepAdaptor_Surface surface(face, /*R=*/false);
    c.type = type_of(surface.GetType());
    if (c.type == CadSurfaceType::kPlane) {
      // The surface normal is X x Y of the plane's frame, which is minus the frame's main
      // direction when the frame is left-handed.
      const gp_Ax3 frame = surface.Plane().Position();
      gp_Dir n = frame.XDirection().Crossed(frame.YDirection());
      if (face.Orientation() == TopAbs_REVERSED) n.Reverse();
      c.axis = xyz(n.XYZ());
      c.location = xyz(frame.Location().XYZ());
    } else if (c.type == CadSurfaceType::kCylinder) {
      gp_Cylinder cyl = surface.Cylinder();
      c.axis = xyz(cyl.Axis().Direction().XYZ());
      c.location = xyz(cyl.Axis().Location().XYZ());
      c.radius = cyl.Radius();
    } else if (c.type == CadSurfaceType::kCone) {
      gp_Cone cone = surface.Cone();
      c.axis = xyz(cone.Axis().Direction().XYZ());
      c.location = xyz(cone.Axis().Location().XYZ());
      c.radius = cone.RefRadius();
    }
  }
  return out;
}

std::string face_label(const TopoDS_Face& face, uint32_t index) {
  std::string s = "face " + std::to_string(index) + " (";
  s += name_of(type_of(BRepAdaptor_Surface(face, false).GetType()));
  Bnd_Box box;
  BRepBndLib::AddOptimal(face, box, /*useTriangulation=*/false, /*useShapeTolerance=*/false);
  if (!box.IsVoid()) {
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    s += ", " + num(x1 - x0) + " x " + num(y1 - y0) + " x " + num(z1 - z0) + " mm";
  }
  GProp_GProps props;
  BRepGProp::SurfaceProperties(face, props);
  s += ", area " + num(std::abs(props.Mass())) + " mm^2)";  // negative on a reversed face
  return s;
}

}  // namespace step_internal
}  // namespace gvm
