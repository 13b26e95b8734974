// The test parts of brep_parts.h, built with BRepPrimAPI and BRepAlgoAPI.
#include "brep_parts.h"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Writer.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax2.hxx>
#include <gp_Trsf.hxx>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace gvm::test {
namespace {

TopoDS_Shape box(double x0, double y0, double z0, double dx, double dy, double dz) {
  return BRepPrimAPI_MakeBox(gp_Pnt(x0, y0, z0), dx, dy, dz).Shape();
}

// A cylinder of radius r from p along d for length h.
TopoDS_Shape cylinder(const gp_Pnt& p, const gp_Dir& d, double r, double h) {
  return BRepPrimAPI_MakeCylinder(gp_Ax2(p, d), r, h).Shape();
}

TopoDS_Shape cut(const TopoDS_Shape& a, const TopoDS_Shape& b) {
  BRepAlgoAPI_Cut op(a, b);
  if (!op.IsDone()) throw std::runtime_error("BRepAlgoAPI_Cut failed");
  return op.Shape();
}

TopoDS_Shape fuse(const TopoDS_Shape& a, const TopoDS_Shape& b) {
  BRepAlgoAPI_Fuse op(a, b);
  if (!op.IsDone()) throw std::runtime_error("BRepAlgoAPI_Fuse failed");
  op.SimplifyResult();  // one face per plane, not the pieces the fuse made
  return op.Shape();
}

const gp_Dir kZ(0, 0, 1), kY(0, 1, 0), kX(1, 0, 0);

TopoDS_Shape build(Part part) {
  const TopoDS_Shape block = box(0, 0, 0, 40, 30, 10);
  switch (part) {
    case Part::kThroughHole: return cut(block, cylinder({20, 15, -1}, kZ, 4, 12));
    case Part::kBlindHole: return cut(block, cylinder({20, 15, 4}, kZ, 4, 7));
    case Part::kCounterbore:
      return cut(cut(block, cylinder({20, 15, -1}, kZ, 3, 12)), cylinder({20, 15, 6}, kZ, 6, 5));
    case Part::kCountersink: {
      // Radius 3 at z = 7 opening to 6 at z = 10 (45 degrees), continued above the block.
      const TopoDS_Shape sink = BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(20, 15, 7), kZ), 3, 7, 4).Shape();
      return cut(cut(block, cylinder({20, 15, -1}, kZ, 3, 12)), sink);
    }
    case Part::kThroughSlot: return cut(block, box(-1, 11, 6, 42, 8, 5));
    case Part::kLBracket: {
      const TopoDS_Shape l = fuse(box(0, 0, 0, 40, 30, 6), box(0, 0, 0, 40, 6, 30));
      return cut(cut(l, cylinder({20, 20, -1}, kZ, 4, 8)), cylinder({20, -1, 20}, kY, 4, 8));
    }
    case Part::kBlockedHole: {
      const TopoDS_Shape c = fuse(fuse(block, box(0, 0, 10, 5, 30, 10)), box(0, 0, 20, 40, 30, 5));
      return cut(c, cylinder({20, 15, -1}, kZ, 4, 12));
    }
  }
  throw std::logic_error("unknown part");
}

}  // namespace

Rotation generic_rotation() {
  gp_Trsf t;
  t.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 2, 3)), 25 * M_PI / 180);
  Rotation r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = t.Value(i + 1, j + 1);
  return r;
}

Vec rotate(const Rotation& r, const Vec& v) {
  Vec out{};
  for (int i = 0; i < 3; ++i) out[i] = r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2];
  return out;
}

const char* name_of(Part part) {
  switch (part) {
    case Part::kThroughHole: return "through_hole";
    case Part::kBlindHole: return "blind_hole";
    case Part::kCounterbore: return "counterbore";
    case Part::kCountersink: return "countersink";
    case Part::kThroughSlot: return "through_slot";
    case Part::kLBracket: return "l_bracket";
    case Part::kBlockedHole: return "blocked_hole";
  }
  return "?";
}

std::string step_bytes(Part part, const Rotation& rotation) {
  TopoDS_Shape shape = build(part);
  gp_Trsf t;
  t.SetValues(rotation[0][0], rotation[0][1], rotation[0][2], 0, rotation[1][0], rotation[1][1], rotation[1][2], 0,
              rotation[2][0], rotation[2][1], rotation[2][2], 0);
  shape = BRepBuilderAPI_Transform(shape, t, /*copy=*/true).Shape();
  STEPControl_Writer writer;
  Interface_Static::SetCVal("write.step.schema", "AP214IS");
  if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone) throw std::runtime_error("STEP transfer failed");
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("gvm_step_part_" + std::to_string(getpid()) + ".stp");
  if (writer.Write(file.c_str()) != IFSelect_RetDone) throw std::runtime_error("STEP write failed");
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  std::filesystem::remove(file);
  return bytes.str();
}

}  // namespace gvm::test
