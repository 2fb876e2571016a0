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
    // TODO(lab06): a world point p is inside when -w <= x, y, z <= w for
    // (x, y, z, w) = viewProjection * (p, 1). Each inequality is a plane:
    // left is row 3 + row 0, right row 3 - row 0, bottom row 3 + row 1, top
    // row 3 - row 1, near row 3 + row 2, far row 3 - row 2 (glm is column-major:
    // row i is (m[0][i], m[1][i], m[2][i], m[3][i])). A row (a, b, c, e) is the
    // plane normal (a, b, c), d = e. Divide each by the length of its normal
    // (docs: "The frustum's planes").
    (void)viewProjection;
    throw NotImplemented("frustumPlanes()");
}

bool sphereInFrustum(const Frustum& frustum, const BoundingSphere& sphere) {
    // TODO(lab06): outside when, for some plane, the signed distance of the
    // centre, dot(n, c) + d, is less than -radius (docs: "Is it inside?").
    (void)frustum;
    (void)sphere;
    throw NotImplemented("sphereInFrustum()");
}

bool boxInFrustum(const Frustum& frustum, const Aabb& box) {
    // TODO(lab06): for each plane, the positive vertex: on each axis, box.max
    // where the normal's component is >= 0, box.min where it is negative. If
    // that corner is outside the plane, so is the whole box (docs: "Is it inside?").
    (void)frustum;
    (void)box;
    throw NotImplemented("boxInFrustum()");
}

} // namespace stoa
