// OFF files past assimp's reader (src/scene/off_faces.h): a face index beyond the vertices and
// polygons of 10 or more corners, which assimp clamps and drops without a word, are refused with
// one line; polygons up to 9 corners, colours and comments load with every triangle.

#include "scene/mesh_loader.h"
#include "scene/off_faces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace vissort {
namespace {

namespace fs = std::filesystem;

// An OFF file with a polygon of n corners (a regular n-gon) and a triangle to the apex.
std::string polygonOff(int n) {
    std::ostringstream off;
    off << "OFF\n# a cap and a side\n" << n + 1 << " 2 0\n";
    for (int i = 0; i < n; ++i)
        off << std::cos(6.283185307 * i / n) << ' ' << std::sin(6.283185307 * i / n) << " 0\n";
    off << "0 0 1\n" << n;
    for (int i = 0; i < n; ++i)
        off << ' ' << i;
    off << " 0.5 0.5 0.5\n3 0 1 " << n << '\n';
    return off.str();
}

Result<Scene> loadText(const std::string& name, const std::string& text) {
    const fs::path file =
        fs::temp_directory_path() / ("vissort_off_" + std::to_string(::getpid()) + "_" + name);
    std::ofstream(file, std::ios::binary) << text;
    Result<Scene> loaded = detail::loadMeshFile(file.string());
    fs::remove(file);
    return loaded;
}

TEST(OffFaces, PolygonsUpToNineCornersLoadWhole) {
    for (int n : {3, 4, 9}) {
        const Result<Scene> loaded = loadText("ok.off", polygonOff(n));
        ASSERT_TRUE(loaded) << loaded.error;
        EXPECT_EQ(loaded.value->triangleCount(), std::size_t(n - 2 + 1)) << n << " corners";
    }
}

TEST(OffFaces, PolygonsAssimpDropsAreRefused) {
    for (int n : {10, 12, 40}) {
        const Result<Scene> loaded = loadText("cap.off", polygonOff(n));
        ASSERT_FALSE(loaded) << n << " corners";
        EXPECT_NE(loaded.error.find("10 or more corners"), std::string::npos) << loaded.error;
        EXPECT_NE(loaded.error.find("one of " + std::to_string(n)), std::string::npos)
            << loaded.error;
        EXPECT_EQ(loaded.error.find('\n'), std::string::npos);
    }
}

TEST(OffFaces, AnIndexBeyondTheVerticesIsRefused) {
    const Result<Scene> loaded =
        loadText("bad.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 7\n");
    ASSERT_FALSE(loaded);
    EXPECT_NE(loaded.error.find("face 1 refers to vertex 7, but the file has 4 vertices"),
              std::string::npos)
        << loaded.error;
}

TEST(OffFaces, ReaderCountsFacesAndNamesProblems) {
    std::istringstream good("COFF\n3 1 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n\n0 1 0 0 0 1 1\n"
                            "3 0 1 2 # a comment\n");
    const Result<detail::OffFaces> faces = detail::readOffFaces(good);
    ASSERT_TRUE(faces) << faces.error;
    EXPECT_EQ(faces.value->fan_triangles, 1u);
    EXPECT_EQ(faces.value->most_corners, 3u);
    std::istringstream short_face("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n");
    EXPECT_NE(detail::readOffFaces(short_face).error.find("declares 4 corners but lists 3"),
              std::string::npos);
    std::istringstream cut("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    EXPECT_NE(detail::readOffFaces(cut).error.find("ends after 1 of its 2 faces"),
              std::string::npos);
    std::istringstream negative("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n");
    EXPECT_NE(detail::readOffFaces(negative).error.find("refers to vertex -1"), std::string::npos);
}

} // namespace
} // namespace vissort
