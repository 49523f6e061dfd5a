// Objects as a user means them (issue 35): --objects mesh|node|file says how a mesh file's
// meshes become objects in every command that loads a scene, a JSON scene's entries are one
// object each, and collisions speak of those objects.

#include <string>

#include "cli_fixture.h"

namespace vissort {
namespace {

TEST_F(Cli, ObjectsOptionGroupsAMeshFilesMeshes) {
    // crabs.obj: two OBJ groups (nodes) of a shell and a claw each, four meshes.
    const std::string crabs = dataPath("meshes/crabs.obj");
    const std::pair<const char*, const char*> cases[] = {
        {"mesh", "objects: 4 "}, {"node", "objects: 2 "}, {"file", "objects: 1 "}};
    for (const auto& [grouping, objects] : cases) {
        SCOPED_TRACE(grouping);
        const RunResult r = run({"info", crabs, "--objects", grouping});
        ASSERT_EQ(r.code, 0) << r;
        EXPECT_NE(r.out.find(objects), std::string::npos) << r;
    }
    const RunResult whole = run({"info", crabs, "--objects", "file"});
    EXPECT_NE(whole.out.find("object 0 'crabs': 6 triangles in 4 parts"), std::string::npos)
        << whole;
    const RunResult order = run({"order", crabs, "--objects", "node"});
    ASSERT_EQ(order.code, 0) << order;
    EXPECT_NE(order.out.find(": 2 objects"), std::string::npos) << order;
}

TEST_F(Cli, ObjectsOptionErrors) {
    expectError({"info", dataPath("meshes/crabs.obj"), "--objects", "meshes"}, kUsage,
                {"--objects: unknown grouping 'meshes'", "did you mean 'mesh'?"});
    expectError({"collide", dataPath("scenes/crabs.json"), "--objects", "mesh"}, kInput,
                {"a JSON scene says it per entry"});
    expectError({"order", "builtin:bunnies", "--objects", "file"}, kInput,
                {"a built-in scene makes its own objects"});
}

// Two copies of crabs.obj far apart, each an entry: no two objects meet (inside a copy claws
// pierce shells, which is one object touching itself). With each mesh an object, the claws and
// shells collide within each copy.
TEST_F(Cli, CollideSpeaksOfTheEntriesOfAJsonScene) {
    const RunResult entries = run({"collide", dataPath("scenes/two_crab_files.json")});
    ASSERT_EQ(entries.code, 0) << entries;
    EXPECT_NE(entries.out.find(", 0 intersecting pairs a frame"), std::string::npos) << entries;
    EXPECT_NE(entries.out.find("colliding objects: 0 pairs"), std::string::npos) << entries;
    const RunResult meshes = run({"collide", dataPath("scenes/two_crab_files_by_mesh.json")});
    ASSERT_EQ(meshes.code, 0) << meshes;
    EXPECT_NE(meshes.out.find(", 8 intersecting pairs a frame"), std::string::npos) << meshes;
    EXPECT_NE(meshes.out.find("colliding objects: 4 pairs"), std::string::npos) << meshes;
    EXPECT_NE(meshes.out.find("'near/crab' and"), std::string::npos) << meshes;
}

} // namespace
} // namespace vissort
