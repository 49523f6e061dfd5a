// Tarjan's strongly connected components, iterative so that long chains (one primitive per
// triangle) cannot overflow the call stack.

#include "tarjan_scc.h"

#include <algorithm>
#include <cassert>
#include <limits>
#include <utility>

namespace vissort::test {

std::vector<std::vector<uint32_t>>
stronglyConnectedComponents(const std::vector<std::vector<uint32_t>>& graph) {
    constexpr uint32_t kUnvisited = std::numeric_limits<uint32_t>::max();
    const uint32_t n = uint32_t(graph.size());
    std::vector<uint32_t> index(n, kUnvisited), low_link(n, 0);
    std::vector<bool> on_stack(n, false);
    std::vector<uint32_t> stack;
    std::vector<std::pair<uint32_t, std::size_t>> call_stack; // (vertex, next successor)
    std::vector<std::vector<uint32_t>> components;
    uint32_t next_index = 0;

    for (uint32_t root = 0; root < n; ++root) {
        if (index[root] != kUnvisited)
            continue;
        call_stack.push_back({root, 0});
        while (!call_stack.empty()) {
            auto& [v, next] = call_stack.back();
            if (next == 0 && index[v] == kUnvisited) {
                index[v] = low_link[v] = next_index++;
                stack.push_back(v);
                on_stack[v] = true;
            }
            if (next < graph[v].size()) {
                const uint32_t w = graph[v][next++];
                assert(w < n);
                if (index[w] == kUnvisited) {
                    call_stack.push_back({w, 0}); // invalidates v and next
                } else if (on_stack[w]) {
                    low_link[v] = std::min(low_link[v], index[w]);
                }
                continue;
            }
            const uint32_t finished = v;
            call_stack.pop_back();
            if (!call_stack.empty()) {
                const uint32_t parent = call_stack.back().first;
                low_link[parent] = std::min(low_link[parent], low_link[finished]);
            }
            if (low_link[finished] == index[finished]) {
                std::vector<uint32_t> component;
                uint32_t w;
                do {
                    w = stack.back();
                    stack.pop_back();
                    on_stack[w] = false;
                    component.push_back(w);
                } while (w != finished);
                std::sort(component.begin(), component.end());
                components.push_back(std::move(component));
            }
        }
    }
    std::sort(components.begin(), components.end());
    return components;
}

std::vector<std::vector<uint32_t>>
cyclicComponents(const std::vector<std::vector<uint32_t>>& graph) {
    std::vector<std::vector<uint32_t>> cycles;
    for (std::vector<uint32_t>& component : stronglyConnectedComponents(graph)) {
        if (component.size() >= 2)
            cycles.push_back(std::move(component));
    }
    return cycles;
}

} // namespace vissort::test
