#pragma once
// The contact network at one instant: what the measures, the snapshots and the run file see of
// the contacts. Built by Simulation::contactNetwork() on the engine thread at record time
// (never per step); immutable afterwards, so it may be read from any thread.

#include <array>
#include <cstdint>
#include <vector>

namespace grainlab {

/// One touching contact between grain `first` (A) and the image of grain `second` (B).
struct ContactRecord {
    std::int32_t first = 0;  ///< grain A
    std::int32_t second = 0; ///< grain B
    std::int32_t shift1 = 0; ///< periodic image shift k of B (cell vectors)
    std::int32_t shift2 = 0;
    double branch1 = 0, branch2 = 0; ///< l = x_B + h k - x_A [m]
    double normal1 = 0, normal2 = 0; ///< unit normal n from A to B
    double point1 = 0, point2 = 0;   ///< contact point minus x_A [m]
    double overlap = 0;              ///< delta [m]
    double normalForce = 0;          ///< f_n >= 0 [N] (B pushed along +n)
    double tangentialForce = 0;      ///< f_t along t = (-n2, n1) [N]
    bool sliding = false;            ///< at the Coulomb limit

    /// Force on B from A, (f1, f2) [N].
    std::array<double, 2> force() const {
        return {normalForce * normal1 - tangentialForce * normal2,
                normalForce * normal2 + tangentialForce * normal1};
    }
};

struct ContactNetwork {
    std::int32_t grainCount = 0;
    std::array<double, 4> cell{};             ///< h, column-major [m]
    std::vector<double> x1, x2;               ///< grain centres, wrapped into the cell [m]
    std::vector<double> grainArea;            ///< [m^2]
    std::vector<double> grainMass;            ///< [kg]
    std::vector<double> netForce1, netForce2; ///< sum of contact forces on each grain [N]
    std::vector<ContactRecord> contacts;      ///< touching contacts, sorted by (first, second)

    double cellArea() const { return cell[0] * cell[3] - cell[1] * cell[2]; }
};

/// The contacts of a network as one array per field, in the network's order: the layout in
/// which the run file and the Python module hand them out.
struct ContactColumns {
    std::vector<std::int32_t> first, second, shift1, shift2;
    std::vector<double> normal1, normal2;
    std::vector<double> point1, point2; ///< the contact point itself, x_A + point [m]
    std::vector<double> branch1, branch2;
    std::vector<double> overlap, normalForce, tangentialForce;
    std::vector<std::uint8_t> sliding; ///< 1 at the Coulomb limit, else 0
};

ContactColumns contactColumns(const ContactNetwork& network);

} // namespace grainlab
