// Ear clipping: n - 2 triangles turning like the polygon whose areas sum to its area, and
// brute force: a point well inside the polygon lies in exactly one triangle, a point outside in
// none. On hand-made non-convex polygons in both orientations and on the fixture's void cells.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "grainlab/ui/polygon_triangulation.h"
#include "grainlab/ui/scene_renderer.h"
#include "overlay_points.h"
#include "test_scenes.h"

namespace grainlab::ui {
namespace {

double twiceSignedArea(QPointF a, QPointF b, QPointF c) {
    return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

double polygonArea(const QPolygonF& p) {
    double twice = 0.0;
    for (qsizetype k = 0; k < p.size(); ++k) {
        const QPointF a = p[k], b = p[(k + 1) % p.size()];
        twice += a.x() * b.y() - b.x() * a.y();
    }
    return 0.5 * twice;
}

/// Checks the triangulation of `p`; `bruteForce` also samples points.
void expectTriangulates(const QPolygonF& p, bool bruteForce, const std::string& name) {
    const auto triangles = triangulatePolygon(p);
    ASSERT_EQ(triangles.size(), std::size_t(p.size() - 2)) << name;
    const double area = polygonArea(p);
    double sum = 0.0;
    for (const auto& t : triangles) {
        const double twice = twiceSignedArea(p[t[0]], p[t[1]], p[t[2]]);
        EXPECT_GE(twice * area, -1e-12 * std::fabs(area)) << name << ": a triangle turns back";
        sum += 0.5 * twice;
    }
    EXPECT_NEAR(sum, area, 1e-9 * std::fabs(area)) << name;
    if (!bruteForce) {
        return;
    }
    const QRectF box = p.boundingRect();
    std::mt19937 random(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double margin = 1e-6 * std::max(box.width(), box.height());
    for (int k = 0; k < 2000; ++k) {
        const QPointF q(box.left() + u(random) * box.width(), box.top() + u(random) * box.height());
        double edge = 1e300;
        for (qsizetype j = 0; j < p.size(); ++j) {
            edge = std::min(edge, testing::segmentDistance(q, p[j], p[(j + 1) % p.size()]));
        }
        if (edge < margin) {
            continue;
        }
        int inside = 0;
        for (const auto& t : triangles) {
            const double s0 = twiceSignedArea(p[t[0]], p[t[1]], q);
            const double s1 = twiceSignedArea(p[t[1]], p[t[2]], q);
            const double s2 = twiceSignedArea(p[t[2]], p[t[0]], q);
            inside += (s0 > 0 && s1 > 0 && s2 > 0) || (s0 < 0 && s1 < 0 && s2 < 0);
        }
        EXPECT_EQ(inside, p.containsPoint(q, Qt::OddEvenFill) ? 1 : 0)
            << name << " at " << q.x() << "," << q.y();
    }
}

QPolygonF reversed(QPolygonF p) {
    std::reverse(p.begin(), p.end());
    return p;
}

TEST(PolygonTriangulation, NonConvexPolygonsInBothOrientations) {
    const QPolygonF square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const QPolygonF lShape{{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
    const QPolygonF comb{{0, 0}, {5, 0}, {5, 3}, {4, 3}, {4, 1}, {3, 1},
                         {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
    QPolygonF star;
    for (int k = 0; k < 14; ++k) {
        const double radius = k % 2 ? 0.35 : 1.0;
        star << QPointF(radius * std::cos(2 * std::numbers::pi * k / 14),
                        radius * std::sin(2 * std::numbers::pi * k / 14));
    }
    // A collinear vertex on an edge, as when three grain centres of a void cell line up.
    const QPolygonF flat{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}};
    for (const auto& [name, p] :
         {std::pair{"square", square}, std::pair{"L", lShape}, std::pair{"comb", comb},
          std::pair{"star", star}, std::pair{"collinear", flat}}) {
        expectTriangulates(p, true, name);
        expectTriangulates(reversed(p), true, std::string(name) + " reversed");
    }
    EXPECT_TRUE(triangulatePolygon(QPolygonF{{0, 0}, {1, 1}}).empty());
}

TEST(PolygonTriangulation, EveryVoidCellOfTheFixture) {
    SceneRenderer r;
    r.setSnapshot(testing::makeCompactedSnapshot());
    const int cells = static_cast<int>(r.snapshot()->voidCells.size());
    ASSERT_GT(cells, 10);
    for (int v = 0; v < cells; ++v) {
        expectTriangulates(r.voidCellPolygon(v), v < 40, "void cell " + std::to_string(v));
    }
}

} // namespace
} // namespace grainlab::ui
