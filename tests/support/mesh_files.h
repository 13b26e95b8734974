// Test parts written to files, so that they go through the same reader and analysis as
// any part a user gives.
#pragma once

#include <filesystem>
#include <string>

#include "gvm/mesh.h"

namespace gvm::test {

// Writes the mesh as OBJ (coordinates exactly, "%.17g"), each face under the name of its
// group (`g name`), so that the groups become the features; returns the path.
std::string write_obj(const RawMesh& raw, const std::filesystem::path& path);

// Writes the points and faces as OFF, coordinates exactly ("%.17g"); returns the path.
std::string write_off(const RawMesh& raw, const std::filesystem::path& path);

}  // namespace gvm::test
