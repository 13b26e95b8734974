#include "setup_views.h"

#include <tbb/parallel_for.h>

#include "base64.h"
#include "escape.h"
#include "png.h"
#include "snapshot.h"

namespace gvm::report {
namespace {

std::string figure(const StaticView& view, const std::string& png) {
  std::string out = "<figure class=\"snapshot\"";
  if (view.setup) out += " data-setup=\"" + std::to_string(*view.setup) + "\"";
  out += "><img alt=\"" + html_escape(view.caption) + "\" src=\"data:image/png;base64," + base64(png) + "\">";
  return out + "<figcaption>" + html_escape(view.caption) + "</figcaption></figure>\n";
}

}  // namespace

std::string static_views(const SolidMesh& mesh, const FaceClasses& classes, const std::vector<StaticView>& views) {
  std::vector<std::array<double, 3>> points;
  points.reserve(mesh.points.size());
  for (const Point3& p : mesh.points) points.push_back({p.x, p.y, p.z});
  std::vector<std::string> figures(views.size());
  tbb::parallel_for(size_t{0}, views.size(), [&](size_t i) {
    const StaticView& view = views[i];
    std::vector<Rgb> palette;
    for (size_t c = 0; c < classes.classes.size(); ++c) {
      const std::string& color = classes.classes[c].color;
      const bool keep = !view.highlight || *view.highlight == static_cast<int32_t>(c);
      palette.push_back(rgb_of(keep ? color : faded(color)));
    }
    std::vector<Rgb> colors;
    colors.reserve(mesh.triangles.size());
    for (uint32_t face : mesh.triangle_face) colors.push_back(palette[classes.face_class[face]]);
    const Image image = render_snapshot(points, mesh.triangles, colors, {view.toward_viewer, 480});
    figures[i] = figure(view, encode_png(image));
  });
  std::string out;
  for (const std::string& f : figures) out += f;
  return out;
}

}  // namespace gvm::report
