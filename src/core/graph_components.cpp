// Strongly connected components in topological order (graph_components.h): Tarjan (1972), with
// an explicit stack, since a stuck set of thousands of primitives would nest that deep.

#include "graph_components.h"

#include <algorithm>

namespace vissort::detail {
namespace {

// Edges grouped by their source (or, reversed, by their target): node u's are
// targets[start[u] .. start[u + 1]).
struct Adjacency {
    std::vector<uint32_t> start, targets;

    Adjacency(uint32_t n, std::span<const Occlusion> edges, bool reversed) : start(n + 1, 0) {
        for (const Occlusion& e : edges)
            ++start[(reversed ? e.back : e.front) + 1];
        for (uint32_t u = 0; u < n; ++u)
            start[u + 1] += start[u];
        targets.resize(edges.size());
        std::vector<uint32_t> next(start.begin(), start.end() - 1);
        for (const Occlusion& e : edges)
            targets[next[reversed ? e.back : e.front]++] = reversed ? e.front : e.back;
    }
    std::span<const uint32_t> of(uint32_t u) const {
        return std::span(targets).subspan(start[u], start[u + 1] - start[u]);
    }
};

constexpr uint32_t kUnvisited = ~0u;

// A breadth-first tree over `adjacency` from members[0] within the component (component_of ==
// id): its edges, as front -> back of the graph (reversed when the adjacency is).
void treeWithin(const Adjacency& adjacency, bool reversed, std::span<const uint32_t> members,
                const std::vector<uint32_t>& component_of, uint32_t id,
                std::vector<uint8_t>& reached, std::vector<Occlusion>& witness) {
    std::vector<uint32_t> queue{members[0]};
    reached[members[0]] = 1;
    for (std::size_t i = 0; i < queue.size(); ++i) {
        const uint32_t u = queue[i];
        for (uint32_t v : adjacency.of(u)) {
            if (component_of[v] != id || reached[v])
                continue;
            reached[v] = 1;
            queue.push_back(v);
            witness.push_back(reversed ? Occlusion{v, u} : Occlusion{u, v});
        }
    }
    for (uint32_t u : queue)
        reached[u] = 0;
}

} // namespace

std::vector<SourceComponent> graphComponents(uint32_t n, std::span<const Occlusion> edges) {
    const Adjacency out(n, edges, false);
    std::vector<uint32_t> index(n, kUnvisited), low(n), component_of(n, kUnvisited);
    std::vector<uint32_t> stack; // Tarjan's stack of visited nodes not yet in a component
    std::vector<uint8_t> on_stack(n, 0);
    struct Frame {
        uint32_t node, next_edge;
    };
    std::vector<Frame> calls;
    std::vector<SourceComponent> components; // sinks first, reversed at the end
    uint32_t counter = 0;
    for (uint32_t root = 0; root < n; ++root) {
        if (index[root] != kUnvisited)
            continue;
        calls.push_back({root, out.start[root]});
        index[root] = low[root] = counter++;
        stack.push_back(root);
        on_stack[root] = 1;
        while (!calls.empty()) {
            Frame& frame = calls.back();
            const uint32_t u = frame.node;
            if (frame.next_edge < out.start[u + 1]) {
                const uint32_t v = out.targets[frame.next_edge++];
                if (index[v] == kUnvisited) {
                    index[v] = low[v] = counter++;
                    stack.push_back(v);
                    on_stack[v] = 1;
                    calls.push_back({v, out.start[v]});
                } else if (on_stack[v]) {
                    low[u] = std::min(low[u], index[v]);
                }
                continue;
            }
            calls.pop_back();
            if (!calls.empty())
                low[calls.back().node] = std::min(low[calls.back().node], low[u]);
            if (low[u] != index[u])
                continue;
            // u is the root of a component: the stack down to it.
            SourceComponent component;
            uint32_t v;
            do {
                v = stack.back();
                stack.pop_back();
                on_stack[v] = 0;
                component_of[v] = uint32_t(components.size());
                component.members.push_back(v);
            } while (v != u);
            std::sort(component.members.begin(), component.members.end());
            components.push_back(std::move(component));
        }
    }
    // Witnesses: a tree out of the first member and a tree into it, within the component.
    const Adjacency in(n, edges, true);
    std::vector<uint8_t> reached(n, 0);
    for (uint32_t id = 0; id < components.size(); ++id) {
        SourceComponent& c = components[id];
        if (c.members.size() < 2)
            continue;
        treeWithin(out, false, c.members, component_of, id, reached, c.witness);
        treeWithin(in, true, c.members, component_of, id, reached, c.witness);
    }
    std::reverse(components.begin(), components.end());
    return components;
}

} // namespace vissort::detail
