// gvm_make_pocket_part N K [FLARE] > part.off: the scaling family of the benchmark. A round plate
// with a round pocket that bulges out below its opening (an undercut; the opening is a
// little wider than the floor, so the floor sees a narrow cone), both N-gons; the
// pocket wall has K rings of quads. The pocket floor (N triangles) sees out through the
// opening, which the upper rings of the wall overhang: its O_S grows with 2 N K wall
// triangles, so |S| |O_S| grows about as N^2 K; the part has N (6 + 2 K) triangles.
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: gvm_make_pocket_part N K [FLARE] > part.off   (N >= 3, K >= 2)\n");
    return 2;
  }
  const int n = std::atoi(argv[1]), k = std::atoi(argv[2]);
  // FLARE: how much wider the opening is than the floor (default 2). With 0 the floor's
  // rim looks straight up past the opening's rim, touching it: the floor sees the axis
  // alone (tests/data/flared_pocket_16_4_0.off).
  const double flare = argc == 4 ? std::atof(argv[3]) : 2;
  if (n < 3 || k < 2) {
    std::fprintf(stderr, "gvm_make_pocket_part: N >= 3 and K >= 2\n");
    return 2;
  }
  const double pi = 3.14159265358979323846;
  const double floor_r = 10, bulge = 6, depth = 15, plate_r = 40, bottom_z = -25;
  struct P {
    double x, y, z;
  };
  std::vector<P> v;
  auto ring = [&](double r, double z) {
    const int first = static_cast<int>(v.size());
    for (int i = 0; i < n; ++i) {
      v.push_back({r * std::cos(2 * pi * i / n), r * std::sin(2 * pi * i / n), z});
    }
    return first;
  };
  std::vector<int> wall(k + 1);  // from the floor (j = 0) up to the opening (j = K)
  for (int j = 0; j <= k; ++j) {
    const double t = double(j) / k;
    wall[j] = ring(floor_r + flare * t + bulge * std::sin(pi * t), -depth + depth * t);
  }
  const int rim = ring(plate_r, 0), bottom = ring(plate_r, bottom_z);
  const int floor_centre = static_cast<int>(v.size());
  v.push_back({0, 0, -depth});
  const int bottom_centre = static_cast<int>(v.size());
  v.push_back({0, 0, bottom_z});

  std::vector<std::array<int, 3>> f;
  auto at = [&](int first, int i) { return first + (i % n); };
  // Counter-clockwise seen from outside the solid.
  for (int j = 0; j < k; ++j) {  // pocket wall, facing the axis
    for (int i = 0; i < n; ++i) {
      f.push_back({at(wall[j], i), at(wall[j + 1], i + 1), at(wall[j], i + 1)});
      f.push_back({at(wall[j], i), at(wall[j + 1], i), at(wall[j + 1], i + 1)});
    }
  }
  for (int i = 0; i < n; ++i) {
    f.push_back({floor_centre, at(wall[0], i), at(wall[0], i + 1)});             // floor
    f.push_back({at(wall[k], i), at(rim, i), at(rim, i + 1)});                   // top
    f.push_back({at(wall[k], i), at(rim, i + 1), at(wall[k], i + 1)});
    f.push_back({at(bottom, i), at(bottom, i + 1), at(rim, i + 1)});             // side
    f.push_back({at(bottom, i), at(rim, i + 1), at(rim, i)});
    f.push_back({bottom_centre, at(bottom, i + 1), at(bottom, i)});              // bottom
  }
  std::printf("OFF\n%zu %zu 0\n", v.size(), f.size());
  for (const P& p : v) std::printf("%.17g %.17g %.17g\n", p.x, p.y, p.z);
  for (const auto& t : f) std::printf("3 %d %d %d\n", t[0], t[1], t[2]);
  return 0;
}
