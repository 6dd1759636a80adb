#pragma once
// Measures of cyclic tests and of stress probes, from recorded series: reversals of the axial
// strain, cycles until the mean stress falls below a fraction of its initial value (the
// liquefaction analogue), the q - eps1 loop of each cycle, and the incremental response envelope
// of a probe set with its linearity and its fit by a linear map (Gudehus' response envelopes:
// a linear response maps the circle of input directions onto an ellipse centred at the origin).
// Pure functions, used by the CLI, the report, the window and studies on their own threads.

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace grainlab {

/// Indices i where the series turns: the increment into i and the increment out of i have
/// opposite signs (zero increments are skipped, a turn over a flat stretch is placed at its
/// first record).
std::vector<std::size_t> reversalIndices(const std::vector<double>& series);

/// A cycle's records [begin, end]: from one upper peak of eps1 to the next (reversals 2k and
/// 2k + 2 of reversalIndices). The loading leg before the first reversal belongs to no cycle.
struct CycleSpan {
    std::size_t begin = 0, end = 0;
};
std::vector<CycleSpan> cycleSpans(const std::vector<std::size_t>& reversals);

struct PressureCriterionResult {
    std::size_t index = 0; ///< first record with p < fraction p0
    double cycles = 0;     ///< reversals before it, halved: cycles to the criterion [-]
};
/// The first record where p < fraction * p0, with the cycle count reached then; none if never.
std::optional<PressureCriterionResult>
cyclesToPressureFraction(const std::vector<double>& p, const std::vector<std::size_t>& reversals,
                         double p0, double fraction);

/// Unit input directions of K probes evenly spread over the circle: (cos 2 pi k/K, sin 2 pi k/K).
std::vector<std::array<double, 2>> probeDirections(std::size_t count);

struct ResponseEnvelope {
    std::vector<std::array<double, 2>> points; ///< the responses, in direction order
    /// max over opposite pairs (k, k + K/2) of |r_k + r_opp| / mean(|r_k|, |r_opp|): 0 for a
    /// response linear in the increment (opposite inputs give opposite responses) [-]
    double asymmetry = 0;
    /// The best linear map M (least squares) with r_k ~ M u_k, column-major (m11, m21, m12, m22).
    std::array<double, 4> linearMap{};
    /// sqrt(sum |r_k - M u_k|^2 / sum |r_k|^2): 0 when the envelope is an ellipse centred at the
    /// origin, the image of the unit circle under M [-]
    double ellipseResidual = 0;
    double majorSemiAxis = 0; ///< larger singular value of M [response unit]
    double minorSemiAxis = 0; ///< smaller singular value of M [response unit]
    double majorAngle = 0;    ///< angle of the major axis from the first response axis [rad]
};

/// The envelope of K responses to the inputs of probeDirections(K) (K even, >= 4; refused
/// otherwise with std::invalid_argument).
ResponseEnvelope responseEnvelope(const std::vector<std::array<double, 2>>& responses);

} // namespace grainlab
