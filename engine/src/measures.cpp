#include "grainlab/measures.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

namespace grainlab {

namespace {

void checkContactIndices(const ContactNetwork& network) {
    const std::int32_t n = network.grainCount;
    for (std::size_t c = 0; c < network.contacts.size(); ++c) {
        const ContactRecord& r = network.contacts[c];
        if (r.first < 0 || r.first >= n || r.second < 0 || r.second >= n) {
            throw std::invalid_argument(fmt::format("contact {}: grains ({}, {}) outside 0..{}", c,
                                                    r.first, r.second, n - 1));
        }
    }
}

/// Contacts per grain; a contact of a grain with its own image counts twice.
std::vector<std::int32_t> contactDegrees(const ContactNetwork& network) {
    checkContactIndices(network);
    std::vector<std::int32_t> degree(network.grainCount, 0);
    for (const ContactRecord& r : network.contacts) {
        ++degree[r.first];
        ++degree[r.second];
    }
    return degree;
}

double forceMagnitudeSquared(const ContactRecord& r) {
    return contactForceSquared(r.normalForce, r.tangentialForce);
}

} // namespace

CoordinationCounts coordinationCounts(const ContactNetwork& network) {
    const std::vector<std::int32_t> degree = contactDegrees(network);
    CoordinationCounts c;
    c.grains = network.grainCount;
    c.contacts = static_cast<std::int32_t>(network.contacts.size());
    for (std::int32_t d : degree) {
        c.rattlers += d == 0 ? 1 : 0;
        c.singleContact += d == 1 ? 1 : 0;
    }
    if (c.grains > 0) {
        c.coordination = 2.0 * c.contacts / c.grains;
    }
    const std::int32_t denominator = c.grains - c.rattlers - c.singleContact;
    if (denominator > 0) {
        c.mechanicalCoordination = (2.0 * c.contacts - c.singleContact) / denominator;
    }
    return c;
}

LoadBearingGraph loadBearingGraph(const ContactNetwork& network) {
    std::vector<std::int32_t> degree = contactDegrees(network);
    const std::int32_t n = network.grainCount;
    const std::size_t m = network.contacts.size();
    // Incidence lists (CSR) so that pruning a grain visits only its own contacts.
    std::vector<std::int32_t> start(n + 1, 0);
    for (const ContactRecord& r : network.contacts) {
        ++start[r.first + 1];
        ++start[r.second + 1];
    }
    for (std::int32_t i = 0; i < n; ++i) {
        start[i + 1] += start[i];
    }
    std::vector<std::int32_t> incident(start[n]);
    std::vector<std::int32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t c = 0; c < m; ++c) {
        incident[fill[network.contacts[c].first]++] = static_cast<std::int32_t>(c);
        incident[fill[network.contacts[c].second]++] = static_cast<std::int32_t>(c);
    }

    LoadBearingGraph g;
    g.grainInGraph.assign(n, 1);
    g.contactInGraph.assign(m, 1);
    std::vector<std::int32_t> queue;
    for (std::int32_t i = 0; i < n; ++i) {
        if (degree[i] < 2) {
            queue.push_back(i);
            g.grainInGraph[i] = 0;
        }
    }
    // Removing a grain removes its remaining contacts; a neighbour that drops below two
    // contacts is removed in turn.
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const std::int32_t i = queue[head];
        for (std::int32_t k = start[i]; k < start[i + 1]; ++k) {
            const std::int32_t c = incident[k];
            if (!g.contactInGraph[c]) {
                continue;
            }
            g.contactInGraph[c] = 0;
            const ContactRecord& r = network.contacts[c];
            for (std::int32_t j : {r.first, r.second}) {
                --degree[j];
                if (g.grainInGraph[j] && degree[j] < 2) {
                    g.grainInGraph[j] = 0;
                    queue.push_back(j);
                }
            }
        }
    }
    for (std::int32_t i = 0; i < n; ++i) {
        g.grains += g.grainInGraph[i];
    }
    for (std::size_t c = 0; c < m; ++c) {
        g.contacts += g.contactInGraph[c];
    }
    if (g.grains > 0) {
        g.coordination = 2.0 * g.contacts / g.grains;
    }
    return g;
}

FabricTensor fabricTensor(const ContactNetwork& network, const std::vector<std::uint8_t>& mask) {
    if (!mask.empty() && mask.size() != network.contacts.size()) {
        throw std::invalid_argument(fmt::format("fabric: mask of {} entries for {} contacts",
                                                mask.size(), network.contacts.size()));
    }
    FabricTensor f;
    for (std::size_t c = 0; c < network.contacts.size(); ++c) {
        if (!mask.empty() && !mask[c]) {
            continue;
        }
        const ContactRecord& r = network.contacts[c];
        f.h11 += r.normal1 * r.normal1;
        f.h22 += r.normal2 * r.normal2;
        f.h12 += r.normal1 * r.normal2;
        ++f.contacts;
    }
    if (f.contacts > 0) {
        f.h11 /= f.contacts;
        f.h22 /= f.contacts;
        f.h12 /= f.contacts;
    }
    f.deviator = f.h11 - f.h22;
    const double trace = f.h11 + f.h22;
    if (trace > 0.0) {
        f.ratio = f.deviator / trace;
    }
    return f;
}

double strongForceThreshold(const ContactNetwork& network, StrongForceThreshold kind) {
    const std::size_t m = network.contacts.size();
    if (m == 0) {
        return 0.0;
    }
    double sum = 0;
    for (const ContactRecord& r : network.contacts) {
        sum += kind == StrongForceThreshold::RmsForce ? forceMagnitudeSquared(r) : r.normalForce;
    }
    return kind == StrongForceThreshold::RmsForce ? std::sqrt(sum / m) : sum / m;
}

StrongWeakFabric strongWeakFabric(const ContactNetwork& network, StrongForceThreshold kind) {
    StrongWeakFabric s;
    s.threshold = strongForceThreshold(network, kind);
    std::vector<std::uint8_t> strong(network.contacts.size()), weak(network.contacts.size());
    for (std::size_t c = 0; c < network.contacts.size(); ++c) {
        const ContactRecord& r = network.contacts[c];
        const bool isStrong = kind == StrongForceThreshold::RmsForce
                                  ? std::sqrt(forceMagnitudeSquared(r)) > s.threshold
                                  : r.normalForce > s.threshold;
        strong[c] = isStrong ? 1 : 0;
        weak[c] = isStrong ? 0 : 1;
    }
    if (network.contacts.empty()) {
        return s; // an empty mask would mean "all contacts"
    }
    s.strong = fabricTensor(network, strong);
    s.weak = fabricTensor(network, weak);
    return s;
}

std::int32_t slidingContactCount(const ContactNetwork& network) {
    return static_cast<std::int32_t>(
        std::count_if(network.contacts.begin(), network.contacts.end(),
                      [](const ContactRecord& r) { return r.sliding; }));
}

double unbalancedForceIndex(const ContactNetwork& network) {
    const std::int32_t n = network.grainCount;
    if (network.contacts.empty() || n == 0) {
        return 0.0;
    }
    if (network.netForce1.size() != static_cast<std::size_t>(n) ||
        network.netForce2.size() != static_cast<std::size_t>(n)) {
        throw std::invalid_argument(
            fmt::format("unbalanced force: net forces of {} grains, network has {}",
                        network.netForce1.size(), n));
    }
    double contactSum = 0;
    for (const ContactRecord& r : network.contacts) {
        contactSum += forceMagnitudeSquared(r);
    }
    return unbalancedForceIndex(contactSum, network.contacts.size(), network.netForce1,
                                network.netForce2);
}

double unbalancedForceIndex(double contactSum, std::size_t contacts,
                            const std::vector<double>& netForce1,
                            const std::vector<double>& netForce2) {
    const std::size_t n = netForce1.size();
    if (contacts == 0 || n == 0 || !(contactSum > 0.0)) {
        return 0.0;
    }
    double grainSum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        grainSum += netForce1[i] * netForce1[i] + netForce2[i] * netForce2[i];
    }
    return std::sqrt((grainSum / double(n)) / (contactSum / double(contacts))) * 100.0;
}

double voidRatio(const ContactNetwork& network) {
    double solid = 0;
    for (double a : network.grainArea) {
        solid += a;
    }
    if (!(solid > 0.0)) {
        return 0.0;
    }
    return (std::fabs(network.cellArea()) - solid) / solid;
}

double meanEquivalentDiameter(const ContactNetwork& network) {
    if (network.grainArea.empty()) {
        return 0.0;
    }
    double sum = 0;
    for (double a : network.grainArea) {
        sum += std::sqrt(4.0 * std::max(a, 0.0) / std::numbers::pi);
    }
    return sum / network.grainArea.size();
}

StressMeasures stressMeasures(const Stress& stress) {
    StressMeasures s;
    s.p = 0.5 * (stress.s11 + stress.s22);
    s.q = 0.5 * (stress.s11 - stress.s22);
    if (s.p > 0.0) {
        s.qOverP = s.q / s.p;
        s.phiDeg = std::asin(std::clamp(s.qOverP, -1.0, 1.0)) * 180.0 / std::numbers::pi;
    }
    return s;
}

double inertialNumber(double axialStrainRate, double diameter, double density, double pressure) {
    if (!(pressure > 0.0) || !(density > 0.0)) {
        return 0.0;
    }
    return std::fabs(axialStrainRate) * diameter * std::sqrt(density / pressure);
}

MeasureSet computeMeasures(const ContactNetwork& network, const MeasureOptions& options) {
    MeasureSet m;
    m.counts = coordinationCounts(network);
    m.loadBearing = loadBearingGraph(network);
    m.slidingContacts = slidingContactCount(network);
    if (m.counts.grains > 0) {
        m.slidingIndex = 2.0 * m.slidingContacts / m.counts.grains;
    }
    m.fabric = fabricTensor(network);
    m.strongWeak = strongWeakFabric(network, options.strongThreshold);
    m.unbalancedForce = unbalancedForceIndex(network);
    m.voidRatio = voidRatio(network);
    m.meanDiameter = meanEquivalentDiameter(network);
    if (options.voidCells) {
        m.voidCells =
            computeVoidCells(network, m.loadBearing.contactInGraph, options.voidCellShapes);
    }
    return m;
}

// ---- Time-series columns ----

const std::vector<SeriesColumn>& seriesColumns() {
    static const std::vector<SeriesColumn> columns = {
        {"step", "-"},      {"time", "s"},        {"stage", "-", true},
        {"eps1", "-"},      {"eps2", "-"},        {"epsv", "-"},
        {"DI", "-"},        {"sigma11", "Pa"},    {"sigma22", "Pa"},
        {"sigma12", "Pa"},  {"p", "Pa"},          {"q", "Pa"},
        {"q_over_p", "-"},  {"phi_deg", "deg"},   {"e", "-"},
        {"Np", "-"},        {"Nc", "-"},          {"Z", "-"},
        {"Np_eff", "-"},    {"Nc_eff", "-"},      {"Z_eff", "-"},
        {"Z_m", "-"},       {"N_slip", "-"},      {"S", "-"},
        {"Nv", "-"},        {"Nv_over_Nvi", "-"}, {"valence_mean", "-"},
        {"H11", "-"},       {"H22", "-"},         {"H12", "-"},
        {"Hdev", "-"},      {"Hratio", "-"},      {"Hs11", "-"},
        {"Hs22", "-"},      {"Hs12", "-"},        {"Hsdev", "-"},
        {"Hsratio", "-"},   {"Hw11", "-"},        {"Hw22", "-"},
        {"Hw12", "-"},      {"Hwdev", "-"},       {"Hwratio", "-"},
        {"N_strong", "-"},  {"I_uf", "%"},        {"inertial_number", "-"},
        {"E_kin", "J"},     {"E_elastic", "J"},   {"W_friction", "J"},
        {"W_damping", "J"},
    };
    return columns;
}

std::string seriesHeader(const SeriesColumn& column) {
    // The text column `stage` has no unit: its header is the bare name.
    return column.text ? column.name : column.name + " [" + column.unit + "]";
}

AxisLabel axisLabelOf(const std::string& column) {
    static const std::vector<std::pair<std::string, AxisLabel>> labels = {
        {"time", {"t [s]", 1.0}},
        {"eps1", {"ε1 [%]", 100.0}},
        {"eps2", {"ε2 [%]", 100.0}},
        {"epsv", {"εv [%]", 100.0}},
        {"DI", {"−dεv/dε1", 1.0}},
        {"sigma11", {"σ11 [kPa]", 1e-3}},
        {"sigma22", {"σ22 [kPa]", 1e-3}},
        {"sigma12", {"σ12 [kPa]", 1e-3}},
        {"p", {"p [kPa]", 1e-3}},
        {"q", {"q [kPa]", 1e-3}},
        {"q_over_p", {"q/p", 1.0}},
        {"phi_deg", {"φ [°]", 1.0}},
        {"Z_eff", {"Z̄", 1.0}},
        {"Z_m", {"Z_m", 1.0}},
        {"Nv", {"N_v", 1.0}},
        {"Nv_over_Nvi", {"N_v/N_vi", 1.0}},
        {"valence_mean", {"mean valence", 1.0}},
        {"Hdev", {"H11 − H22", 1.0}},
        {"Hsdev", {"H11 − H22, strong contacts", 1.0}},
        {"Hwdev", {"H11 − H22, weak contacts", 1.0}},
        {"Hratio", {"(H11 − H22)/(H11 + H22)", 1.0}},
        {"Hsratio", {"(H11 − H22)/(H11 + H22), strong contacts", 1.0}},
        {"Hwratio", {"(H11 − H22)/(H11 + H22), weak contacts", 1.0}},
        {"inertial_number", {"I", 1.0}},
    };
    for (const auto& [name, label] : labels) {
        if (name == column) {
            return label;
        }
    }
    for (const SeriesColumn& c : seriesColumns()) {
        if (c.name == column && !c.text) {
            return {c.unit == "-" ? c.name : c.name + " [" + c.unit + "]", 1.0};
        }
    }
    return {column, 1.0};
}

std::vector<double> seriesRow(const MeasureSet& m, const RecordInputs& in) {
    const StressMeasures s = stressMeasures(in.stress);
    const double diameter = in.meanDiameter > 0.0 ? in.meanDiameter : m.meanDiameter;
    const auto fabric = [](std::vector<double>& row, const FabricTensor& f) {
        row.insert(row.end(), {f.h11, f.h22, f.h12, f.deviator, f.ratio});
    };
    std::vector<double> row;
    row.reserve(seriesColumns().size() - 1);
    row.insert(row.end(), {static_cast<double>(in.step), in.time, in.eps1, in.eps2, in.epsv,
                           in.dilatancyIndex, in.stress.s11, in.stress.s22, in.stress.s12, s.p, s.q,
                           s.qOverP, s.phiDeg, m.voidRatio});
    row.insert(row.end(),
               {double(m.counts.grains), double(m.counts.contacts), m.counts.coordination,
                double(m.loadBearing.grains), double(m.loadBearing.contacts),
                m.loadBearing.coordination, m.counts.mechanicalCoordination,
                double(m.slidingContacts), m.slidingIndex});
    const double nv = m.voidCells.voidCount;
    row.insert(row.end(), {nv, in.initialVoidCount > 0.0 ? nv / in.initialVoidCount : 0.0,
                           m.voidCells.meanValence});
    fabric(row, m.fabric);
    fabric(row, m.strongWeak.strong);
    fabric(row, m.strongWeak.weak);
    row.push_back(m.strongWeak.strong.contacts);
    row.push_back(m.unbalancedForce);
    row.push_back(inertialNumber(in.strainRate1, diameter, in.density, s.p));
    row.insert(row.end(), {in.energies.kinetic, in.energies.elastic, in.energies.frictionWork,
                           in.energies.dampingWork});
    if (row.size() != seriesColumns().size() - 1) {
        throw std::logic_error(fmt::format("series row of {} values for {} numeric columns",
                                           row.size(), seriesColumns().size() - 1));
    }
    return row;
}

} // namespace grainlab
