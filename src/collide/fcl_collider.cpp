// The FCL peer of collision detection: FCL's dynamic AABB tree over the objects, one BVH of
// OBBRSS volumes per object refitted every frame, and FCL's own mesh-mesh collision with its own
// triangle test, asked for every contact. It decides touching in floating point, so it may miss
// or invent pairs that the exact test decides otherwise: the tests measure how many.
// This work is based on: Jia Pan, Sachin Chitta, Dinesh Manocha, "FCL: A General Purpose Library
// for Collision and Proximity Queries", ICRA 2012 (the library, 0.7); OBBRSS after Eric Larsen,
// Stefan Gottschalk, Ming Lin, Dinesh Manocha, "Fast Proximity Queries with Swept Sphere
// Volumes", 1999.

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>

#include "collide/peer_colliders.h"

namespace vissort::detail {
namespace {

using Model = fcl::BVHModel<fcl::OBBRSS<double>>;

class FclCollider final : public Collider {
public:
    explicit FclCollider(std::span<const PrimitiveRange> objects)
        : objects_(objects.begin(), objects.end()) {
        // Every contact: FCL stops a pair's traversal once it holds num_max_contacts.
        request_.num_max_contacts = std::size_t(1) << 40;
        request_.enable_contact = true;
    }

    ~FclCollider() override { manager_.clear(); }

    void collide(PositionsView positions, CollisionResult& result) override {
        StageClock clock;
        if (bodies_.empty() && !objects_.empty())
            build(positions);
        else
            update(positions);
        result.stats.update_ms = clock.lap();

        in_pair_.assign(objects_.size(), 0);
        frame_ = &result;
        manager_.collide(this, &FclCollider::collidePair);
        frame_ = nullptr;
        for (uint8_t in : in_pair_)
            result.stats.candidate_objects += in;
        // FCL may report one triangle pair more than once (a contact per intersection point).
        std::sort(result.pairs.begin(), result.pairs.end());
        result.pairs.erase(std::unique(result.pairs.begin(), result.pairs.end()),
                           result.pairs.end());
        // FCL's tests run inside its traversal: all of it is culling here, exact_ms stays 0.
        result.stats.cull_ms = clock.lap();
    }

private:
    struct Body {
        uint32_t object = 0;
        std::shared_ptr<Model> model;
        std::unique_ptr<fcl::CollisionObject<double>> collision_object;
    };

    /// One triangle soup per object: corner c of local triangle i is vertex 3i + c, as in
    /// TrianglePositions, so FCL's primitive ids are local triangle ids.
    void fillVertices(PositionsView positions, PrimitiveRange range) {
        vertices_.resize(3 * std::size_t(range.triangle_count));
        const std::size_t first = 3 * std::size_t(range.first_triangle);
        for (std::size_t v = 0; v < vertices_.size(); ++v)
            vertices_[v] = {positions.x[first + v], positions.y[first + v], positions.z[first + v]};
    }

    void build(PositionsView positions) {
        std::vector<fcl::CollisionObject<double>*> registered;
        std::vector<fcl::Triangle> triangles;
        for (uint32_t o = 0; o < objects_.size(); ++o) {
            const PrimitiveRange range = objects_[o];
            if (range.triangle_count == 0)
                continue; // FCL rejects empty models; meets nothing
            fillVertices(positions, range);
            triangles.resize(range.triangle_count);
            for (uint32_t i = 0; i < range.triangle_count; ++i)
                triangles[i] = fcl::Triangle(3 * i, 3 * i + 1, 3 * i + 2);
            Body body;
            body.object = o;
            body.model = std::make_shared<Model>();
            body.model->beginModel(int(range.triangle_count), int(vertices_.size()));
            body.model->addSubModel(vertices_, triangles);
            body.model->endModel();
            body.collision_object = std::make_unique<fcl::CollisionObject<double>>(body.model);
            body.collision_object->setUserData(&objects_[o]);
            registered.push_back(body.collision_object.get());
            bodies_.push_back(std::move(body));
        }
        manager_.registerObjects(registered);
        manager_.setup();
    }

    /// Same topology, new vertices: refit each BVH bottom-up, then the object's box, then the
    /// manager's tree.
    void update(PositionsView positions) {
        for (Body& body : bodies_) {
            fillVertices(positions, objects_[body.object]);
            body.model->beginUpdateModel();
            body.model->updateSubModel(vertices_);
            body.model->endUpdateModel(/*refit=*/true, /*bottomup=*/true);
            body.model->computeLocalAABB();
            body.collision_object->computeAABB();
        }
        manager_.update();
    }

    /// The manager's callback for each pair of objects whose boxes overlap; false: go on.
    static bool collidePair(fcl::CollisionObject<double>* o1, fcl::CollisionObject<double>* o2,
                            void* data) {
        auto& self = *static_cast<FclCollider*>(data);
        CollisionResult& frame = *self.frame_;
        const auto* range1 = static_cast<const PrimitiveRange*>(o1->getUserData());
        const auto* range2 = static_cast<const PrimitiveRange*>(o2->getUserData());
        ++frame.stats.object_pairs;
        ++frame.stats.box_object_pairs;
        self.in_pair_[std::size_t(range1 - self.objects_.data())] = 1;
        self.in_pair_[std::size_t(range2 - self.objects_.data())] = 1;

        self.contacts_.clear();
        fcl::collide(o1, o2, self.request_, self.contacts_);
        const std::size_t count = self.contacts_.numContacts();
        // fcl::collide exposes neither its volume tests nor its leaf tests: the contacts it
        // reports (before the dedupe) stand for the triangle pairs it tested.
        frame.stats.triangle_pairs += count;
        frame.stats.box_triangle_pairs += count;
        for (std::size_t i = 0; i < count; ++i) {
            const fcl::Contact<double>& contact = self.contacts_.getContact(i);
            // b1 names a triangle of contact.o1, which is o1's geometry unless FCL swapped them.
            const bool swapped = contact.o1 != o1->collisionGeometry().get();
            const uint32_t t1 = (swapped ? range2 : range1)->first_triangle + uint32_t(contact.b1);
            const uint32_t t2 = (swapped ? range1 : range2)->first_triangle + uint32_t(contact.b2);
            frame.pairs.push_back({std::min(t1, t2), std::max(t1, t2)});
        }
        return false;
    }

    std::vector<PrimitiveRange> objects_;
    std::vector<Body> bodies_; // objects with triangles
    fcl::DynamicAABBTreeCollisionManager<double> manager_;
    fcl::CollisionRequest<double> request_;
    fcl::CollisionResult<double> contacts_; // one object pair's, reused
    std::vector<fcl::Vector3<double>> vertices_;
    std::vector<uint8_t> in_pair_;
    CollisionResult* frame_ = nullptr; // the frame being collided, for the callback
};

} // namespace

std::unique_ptr<Collider> makeFclCollider(std::span<const PrimitiveRange> objects) {
    return std::make_unique<FclCollider>(objects);
}

} // namespace vissort::detail
