// An OpenMesh importer that records the vertex and face lists exactly as a reader delivers
// them, without building a half-edge mesh (OpenMesh's own mesh importer silently repairs
// or drops non-manifold faces, so validation could neither see nor name them).
#pragma once

#include <OpenMesh/Core/IO/importer/BaseImporter.hh>

#include <cstdint>
#include <vector>

#include "gvm/geometry.h"

namespace gvm::mesh_internal {

class RawImporter : public OpenMesh::IO::BaseImporter {
 public:
  std::vector<Point3> points;
  std::vector<std::vector<uint32_t>> faces;
  bool float_vertex_seen = false;  // some reader delivered Vec3f (float precision)
  bool bad_face_index = false;

  using BaseImporter::add_vertex;
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override {
    float_vertex_seen = true;
    points.push_back({double(p[0]), double(p[1]), double(p[2])});
    return OpenMesh::VertexHandle(int(points.size() - 1));
  }
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override {
    points.push_back({p[0], p[1], p[2]});
    return OpenMesh::VertexHandle(int(points.size() - 1));
  }
  OpenMesh::VertexHandle add_vertex() override {
    points.push_back({});
    return OpenMesh::VertexHandle(int(points.size() - 1));
  }
  OpenMesh::HalfedgeHandle add_edge(OpenMesh::VertexHandle, OpenMesh::VertexHandle) override {
    return OpenMesh::HalfedgeHandle();
  }
  OpenMesh::FaceHandle add_face(const VHandles& idx) override {
    std::vector<uint32_t> f;
    f.reserve(idx.size());
    for (auto vh : idx) {
      if (vh.idx() < 0 || size_t(vh.idx()) >= points.size()) bad_face_index = true;
      f.push_back(uint32_t(vh.idx()));
    }
    faces.push_back(std::move(f));
    return OpenMesh::FaceHandle(int(faces.size() - 1));
  }
  OpenMesh::FaceHandle add_face(OpenMesh::HalfedgeHandle) override { return OpenMesh::FaceHandle(); }

  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec2f>&) override {}
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(OpenMesh::FaceHandle, int) override {}
  void set_point(OpenMesh::VertexHandle vh, const OpenMesh::Vec3f& p) override {
    if (vh.idx() >= 0 && size_t(vh.idx()) < points.size()) {
      float_vertex_seen = true;
      points[vh.idx()] = {double(p[0]), double(p[1]), double(p[2])};
    }
  }
  void set_halfedge(OpenMesh::VertexHandle, OpenMesh::HalfedgeHandle) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec2f&) override {}
  void set_status(OpenMesh::VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(OpenMesh::HalfedgeHandle, OpenMesh::HalfedgeHandle) override {}
  void set_face(OpenMesh::HalfedgeHandle, OpenMesh::FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(OpenMesh::HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}

  size_t n_vertices() const override { return points.size(); }
  size_t n_faces() const override { return faces.size(); }
  size_t n_edges() const override { return 0; }
};

}  // namespace gvm::mesh_internal
