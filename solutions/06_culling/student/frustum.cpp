// Lab 06, part 2: the view frustum's planes, and the tests that cull with them.
// Read docs/labs/06_culling.md, "The frustum's planes" and "Is it inside?".
// The app calls frustumPlanes() once per frame with the camera's
// projection * view, then sphereInFrustum() for every object, and
// boxInFrustum() for those whose sphere passed.

#include "lab06.hpp"

#include <stoa/core/NotImplemented.hpp>

#include <glm/glm.hpp>

namespace stoa {

Frustum frustumPlanes(const glm::mat4& viewProjection) {
    const glm::mat4 rows = glm::transpose(viewProjection);   // rows[i]: row i of the matrix
    const glm::vec4 combinations[6] = {
        rows[3] + rows[0],   // left:   x >= -w
        rows[3] - rows[0],   // right:  x <=  w
        rows[3] + rows[1],   // bottom: y >= -w
        rows[3] - rows[1],   // top:    y <=  w
        rows[3] + rows[2],   // near:   z >= -w
        rows[3] - rows[2],   // far:    z <=  w
    };
    Frustum frustum;
    for (int i = 0; i < 6; ++i) {
        const glm::vec3 normal(combinations[i]);
        const float length = glm::length(normal);
        frustum.planes[i] = {normal / length, combinations[i].w / length};
    }
    return frustum;
}

bool sphereInFrustum(const Frustum& frustum, const BoundingSphere& sphere) {
    for (const Plane& plane : frustum.planes)
        if (glm::dot(plane.normal, sphere.center) + plane.d < -sphere.radius) return false;
    return true;
}

bool boxInFrustum(const Frustum& frustum, const Aabb& box) {
    for (const Plane& plane : frustum.planes) {
        const glm::vec3 positive(plane.normal.x >= 0.0f ? box.max.x : box.min.x,
                                 plane.normal.y >= 0.0f ? box.max.y : box.min.y,
                                 plane.normal.z >= 0.0f ? box.max.z : box.min.z);
        if (glm::dot(plane.normal, positive) + plane.d < 0.0f) return false;
    }
    return true;
}

} // namespace stoa
