// order_check: the exact ground truth (ground_truth.h) of one frame's visibility order, for
// tests outside C++ (python/tests/test_batch.py checks vissort.batch's orders with it).
//
//   order_check SCENE WIDTH HEIGHT PATH FRAMES FRAME < order.txt
//
// The frame is the one the command line and the Python module order for these arguments: the
// default camera over FRAMES frames (Camera.default), moved along PATH to FRAME, framing the
// frame's positions, the scene's objects as primitives. Standard input: the order's ids on the
// first line, then one line per declared cycle. Prints "permutation P violations V checked C";
// exits 0 when it could check, 2 on bad arguments or input.

#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "ground_truth.h"
#include "scenes/scene_library.h"
#include "vissort/frame_driver.h"
#include "vissort/view_choice.h"

namespace {

int usage(const std::string& problem) {
    std::cerr << "order_check: " << problem
              << "\nusage: order_check SCENE WIDTH HEIGHT PATH FRAMES FRAME < order.txt\n";
    return 2;
}

std::vector<uint32_t> readIds(const std::string& line) {
    std::istringstream in(line);
    std::vector<uint32_t> ids;
    for (uint32_t id; in >> id;)
        ids.push_back(id);
    return ids;
}

} // namespace

int main(int argc, char** argv) {
    using namespace vissort;
    if (argc != 7)
        return usage("expected 6 arguments");
    const Result<Scene> scene = samples::loadScene(argv[1]);
    if (!scene)
        return usage(scene.error);
    ViewDef def;
    def.width = uint32_t(std::atoi(argv[2]));
    def.height = uint32_t(std::atoi(argv[3]));
    const Result<CameraPath> path = parseCameraPath(argv[4]);
    def.frames = std::atoi(argv[5]);
    const int frame = std::atoi(argv[6]);
    if (def.width < 1 || def.height < 1 || !path || def.frames < 1 || frame < 0)
        return usage("bad size, path, frames or frame");
    def.names = OptionNames::python; // Camera.default's choice
    const Result<ChosenView> view = chooseView(def, *scene.value);
    if (!view)
        return usage(view.error);
    FrameDriver driver(*scene.value, view.value->camera, *path.value, def.width, def.height);
    driver.seek(frame);

    std::string line;
    if (!std::getline(std::cin, line))
        return usage("no order on standard input");
    const std::vector<uint32_t> order = readIds(line);
    std::vector<std::vector<uint32_t>> cycles;
    while (std::getline(std::cin, line))
        if (!line.empty())
            cycles.push_back(readIds(line));

    TrianglePositions positions;
    const PositionsView frame_positions = driver.positions();
    positions.x.assign(frame_positions.x.begin(), frame_positions.x.end());
    positions.y.assign(frame_positions.y.begin(), frame_positions.y.end());
    positions.z.assign(frame_positions.z.begin(), frame_positions.z.end());
    const std::vector<PrimitiveRange> objects = scene.value->objectPrimitives();
    const test::OrderCheck check =
        test::checkVisibilityOrder(positions, driver.view(), objects, order, cycles);
    std::cout << "permutation " << (check.valid_permutation ? 1 : 0) << " violations "
              << check.violation_count << " checked " << check.pairs_checked << '\n';
    return 0;
}
