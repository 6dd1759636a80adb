// See polygon_triangulation.h. Ear clipping (Meisters 1975): an ear is a convex vertex whose
// triangle with its two neighbours holds no other remaining vertex; cutting it off leaves a
// simple polygon with one vertex fewer. O(n^3) in the worst case, which is nothing for void
// cells (3 to a few tens of vertices).
#include "grainlab/ui/polygon_triangulation.h"

namespace grainlab::ui {

std::vector<std::array<int, 3>> triangulatePolygon(const QPolygonF& polygon) {
    const int n = static_cast<int>(polygon.size());
    std::vector<std::array<int, 3>> triangles;
    if (n < 3) {
        return triangles;
    }
    triangles.reserve(n - 2);
    double twiceArea = 0.0;
    for (int i = 0; i < n; ++i) {
        const QPointF& a = polygon[i];
        const QPointF& b = polygon[(i + 1) % n];
        twiceArea += a.x() * b.y() - b.x() * a.y();
    }
    const double orientation = twiceArea >= 0.0 ? 1.0 : -1.0;
    // Twice the signed area of triangle (a, b, c), positive when it turns like the polygon.
    auto turn = [&](int a, int b, int c) {
        const QPointF ab = polygon[b] - polygon[a], ac = polygon[c] - polygon[a];
        return orientation * (ab.x() * ac.y() - ab.y() * ac.x());
    };
    std::vector<int> left(n);
    for (int i = 0; i < n; ++i) {
        left[i] = i;
    }
    int k = 0; // where to look for the next ear
    while (left.size() > 3) {
        const int m = static_cast<int>(left.size());
        bool clipped = false;
        for (int tried = 0; tried < m; ++tried) {
            const int a = left[(k + m - 1) % m], b = left[k], c = left[(k + 1) % m];
            bool ear = turn(a, b, c) > 0.0; // reflex or flat vertices are not ears
            for (std::size_t j = 0; ear && j < left.size(); ++j) {
                // On the triangle's boundary counts as inside: cutting there would overlap.
                const int q = left[j];
                ear = q == a || q == b || q == c || turn(a, b, q) < 0.0 || turn(b, c, q) < 0.0 ||
                      turn(c, a, q) < 0.0;
            }
            if (ear) {
                triangles.push_back({a, b, c});
                left.erase(left.begin() + k);
                k %= m - 1;
                clipped = true;
                break;
            }
            k = (k + 1) % m;
        }
        if (!clipped) {
            break; // degenerate: the rest as a fan below
        }
    }
    for (std::size_t j = 1; j + 1 < left.size(); ++j) {
        triangles.push_back({left[0], left[j], left[j + 1]});
    }
    return triangles;
}

} // namespace grainlab::ui
