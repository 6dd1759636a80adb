#pragma once
// Hand-built contact networks for the measures and void-cell tests.

#include <cmath>
#include <numbers>

#include "grainlab/contact_network.h"
#include "grainlab/periodic_cell.h"

namespace grainlab::test {

/// An empty network of n grains of area `grainArea` and unit mass in the cell h.
inline ContactNetwork emptyNetwork(int n, const CellMatrix& h, double grainArea = 1e-7) {
    ContactNetwork net;
    net.grainCount = n;
    net.cell = h;
    net.x1.assign(n, 0.0);
    net.x2.assign(n, 0.0);
    net.grainArea.assign(n, grainArea);
    net.grainMass.assign(n, 1.0);
    net.netForce1.assign(n, 0.0);
    net.netForce2.assign(n, 0.0);
    return net;
}

/// A contact between grain a and the image (shift k) of grain b, from the grains' positions:
/// normal along the branch, contact point at mid-branch, unit normal force.
inline void addBranchContact(ContactNetwork& net, int a, int b, int k1 = 0, int k2 = 0) {
    const auto& h = net.cell;
    ContactRecord r;
    r.first = a;
    r.second = b;
    r.shift1 = k1;
    r.shift2 = k2;
    r.branch1 = net.x1[b] + h[0] * k1 + h[2] * k2 - net.x1[a];
    r.branch2 = net.x2[b] + h[1] * k1 + h[3] * k2 - net.x2[a];
    const double length = std::hypot(r.branch1, r.branch2);
    r.normal1 = r.branch1 / length;
    r.normal2 = r.branch2 / length;
    r.point1 = 0.5 * r.branch1;
    r.point2 = 0.5 * r.branch2;
    r.normalForce = 1.0;
    net.contacts.push_back(r);
}

/// Hexagonal lattice of nx * ny touching disks of diameter d (ny even) in a periodic cell,
/// contacts by adjacency (3 per grain), unit normal forces.
inline ContactNetwork hexagonalNetwork(int nx, int ny, double d) {
    const double rowHeight = d * std::sqrt(3.0) / 2.0;
    ContactNetwork net =
        emptyNetwork(nx * ny, {nx * d, 0.0, 0.0, ny * rowHeight}, std::numbers::pi * d * d / 4);
    auto id = [&](int i, int j) { return ((j + ny) % ny) * nx + (i + nx) % nx; };
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            net.x1[id(i, j)] = (i + 0.5 * (j % 2) + 0.25) * d;
            net.x2[id(i, j)] = (j + 0.5) * rowHeight;
        }
    }
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            // Right, upper-right and upper-left neighbours.
            const int up = j % 2;
            const int neighbours[3][2] = {{i + 1, j}, {i + up, j + 1}, {i + up - 1, j + 1}};
            for (const auto& nb : neighbours) {
                addBranchContact(net, id(i, j), id(nb[0], nb[1]),
                                 nb[0] >= nx ? 1 : (nb[0] < 0 ? -1 : 0), nb[1] >= ny ? 1 : 0);
            }
        }
    }
    return net;
}

} // namespace grainlab::test
