#pragma once
// Micro-structure measures (docs/measures.md) computed from one ContactNetwork: coordination, the
// load-bearing graph, Thornton's mechanical coordination, sliding index, fabric tensors of all,
// strong and weak contacts, the unbalanced-force index, the void ratio, the void cells (through
// void_cells.h), plus the stress invariants and the ordered list of time-series columns with
// the function that fills one numeric row.
//
// Pure functions of immutable inputs, O(N log N): called at record or display time (never per
// step) on the thread that owns the network — the engine worker in the GUI, the main thread
// headless. Results are plain data and may be handed to any thread. Formulas and references:
// docs/measures.md.

#include <cstdint>
#include <string>
#include <vector>

#include "grainlab/contact_network.h"
#include "grainlab/series.h"
#include "grainlab/stress_and_energies.h"
#include "grainlab/void_cells.h"

namespace grainlab {

/// Which force splits the contacts into strong and weak.
enum class StrongForceThreshold {
    RmsForce,        ///< strong when |f| > f_a = sqrt(sum |f|^2 / N_c) (the default)
    MeanNormalForce, ///< strong when f_n > <f_n> (Radjai et al. 1998)
};

struct MeasureOptions {
    StrongForceThreshold strongThreshold = StrongForceThreshold::RmsForce;
    bool voidCells = true; ///< trace the void cells (Nv, valence); off leaves them empty
    /// With voidCells: keep each cell (its grains, polygon and shape) too. Off keeps only the
    /// summary (counts, valences, total area, the Euler check), the same numbers bit for bit,
    /// with `cells` empty: what a time-series record needs, without a heap block per cell.
    bool voidCellShapes = true;
};

/// Grain and contact counts and the two coordination numbers that need no graph pruning.
struct CoordinationCounts {
    std::int32_t grains = 0;        ///< N_p [-]
    std::int32_t contacts = 0;      ///< N_c [-]
    std::int32_t rattlers = 0;      ///< N_0: grains with no contact [-]
    std::int32_t singleContact = 0; ///< N_1: grains with exactly one contact [-]
    double coordination = 0;        ///< Z = 2 N_c / N_p (0 without grains) [-]
    /// Z_m = (2 N_c - N_1) / (N_p - N_0 - N_1), Thornton (2000); 0 when the denominator is 0 [-]
    double mechanicalCoordination = 0;
};

/// The load-bearing graph: grains with no contact removed, then grains with a single remaining
/// contact removed repeatedly (a grain left with no contact by this pruning goes too): the
/// 2-core of the contact multigraph.
struct LoadBearingGraph {
    std::vector<std::uint8_t> grainInGraph;   ///< per grain: 1 if kept
    std::vector<std::uint8_t> contactInGraph; ///< per contact: 1 if kept
    std::int32_t grains = 0;                  ///< N_p_eff [-]
    std::int32_t contacts = 0;                ///< N_c_eff [-]
    double coordination = 0;                  ///< Z_eff = 2 N_c_eff / N_p_eff (0 if empty) [-]
};

/// Fabric tensor H = (1/N) sum n (x) n over a set of N contacts (all zero when N = 0).
struct FabricTensor {
    double h11 = 0, h22 = 0, h12 = 0; ///< [-]
    double deviator = 0;              ///< H11 - H22 [-]
    double ratio = 0;                 ///< (H11 - H22) / (H11 + H22), 0 when N = 0 [-]
    std::int32_t contacts = 0;        ///< N [-]
};

/// Fabric split by force magnitude (Radjai et al. 1998).
struct StrongWeakFabric {
    FabricTensor strong, weak;
    double threshold = 0; ///< the force separating them [N]
};

/// Stress invariants p, q, q/p (docs/measures.md; x1 axial, compression positive).
struct StressMeasures {
    double p = 0;      ///< (sigma11 + sigma22) / 2 [Pa]
    double q = 0;      ///< (sigma11 - sigma22) / 2 [Pa]
    double qOverP = 0; ///< q / p, 0 when p <= 0 [-]
    double phiDeg = 0; ///< asin(q / p), q / p clamped to [-1, 1] [deg]
};

/// Every measure of docs/measures.md that follows from one contact network.
struct MeasureSet {
    CoordinationCounts counts;
    LoadBearingGraph loadBearing;
    std::int32_t slidingContacts = 0; ///< N_slip [-]
    double slidingIndex = 0;          ///< S = 2 N_slip / N_p [-]
    FabricTensor fabric;              ///< H over all contacts
    StrongWeakFabric strongWeak;      ///< Hs, Hw and the threshold
    double unbalancedForce = 0;       ///< I_uf [%]
    double voidRatio = 0;             ///< e [-]
    double meanDiameter = 0;          ///< mean equivalent diameter sqrt(4 A / pi) [m]
    VoidCellSet voidCells;            ///< empty unless MeasureOptions::voidCells
};

CoordinationCounts coordinationCounts(const ContactNetwork& network);
LoadBearingGraph loadBearingGraph(const ContactNetwork& network);

/// Fabric over the contacts whose mask entry is non-zero; an empty mask selects all contacts.
FabricTensor fabricTensor(const ContactNetwork& network,
                          const std::vector<std::uint8_t>& mask = {});
/// The force threshold of the strong/weak split [N] (0 without contacts).
double strongForceThreshold(const ContactNetwork& network, StrongForceThreshold kind);
StrongWeakFabric strongWeakFabric(const ContactNetwork& network, StrongForceThreshold kind);

/// Contacts flagged as sliding (at the Coulomb limit).
std::int32_t slidingContactCount(const ContactNetwork& network);
/// I_uf = sqrt(sum_p |F_net|^2 / N_p) / sqrt(sum_c |f_c|^2 / N_c) * 100 [%]; 0 without
/// contact force.
double unbalancedForceIndex(const ContactNetwork& network);
/// |f_c|^2 = f_n^2 + f_t^2 of one contact [N^2].
inline double contactForceSquared(double normalForce, double tangentialForce) {
    return normalForce * normalForce + tangentialForce * tangentialForce;
}
/// I_uf from its parts: `contactSum`, contactForceSquared summed in contact order over
/// `contacts` touching contacts, and the net force on every grain (Simulation's
/// unbalancedForceIndex(), which needs no contact geometry, gives the same bits as the network's).
double unbalancedForceIndex(double contactSum, std::size_t contacts,
                            const std::vector<double>& netForce1,
                            const std::vector<double>& netForce2);
/// e = (A_cell - sum A_grains) / sum A_grains [-]; 0 without grains.
double voidRatio(const ContactNetwork& network);
/// Mean of the equivalent diameters sqrt(4 A / pi) [m]; 0 without grains.
double meanEquivalentDiameter(const ContactNetwork& network);
StressMeasures stressMeasures(const Stress& stress);
/// The inertial number of docs/physics.md, I = |axial strain rate| d sqrt(density / p) [-]:
/// the one definition that the series column, the quasi-static warning and the study's
/// inertial-number knob share. 0 when p <= 0. Rate [1/s], d [m], density [kg/m^3], p [Pa].
double inertialNumber(double axialStrainRate, double diameter, double density, double pressure);

MeasureSet computeMeasures(const ContactNetwork& network, const MeasureOptions& options = {});

// ---- Time-series columns (docs/measures.md, the CSV contract; SeriesColumn is in series.h) ----

/// The columns of docs/measures.md in order, `stage` included.
const std::vector<SeriesColumn>& seriesColumns();
/// "name [unit]" (the text column `stage`: its bare name).
std::string seriesHeader(const SeriesColumn& column);

/// How a figure labels a series column, as a paper would print it: the symbol, with the unit of
/// the plotted values ("ε1 [%]", "q [kPa]", "q/p" for a ratio), and the factor from the stored
/// value to the plotted one (100 for strains in percent, 1e-3 for stresses in kPa). The CSVs keep
/// the column names and stored units; only drawings use this.
struct AxisLabel {
    std::string text;
    double scale = 1.0;
};
/// For a column of seriesColumns(); any other name is returned as it is, with scale 1.
AxisLabel axisLabelOf(const std::string& column);

/// What a row needs beyond the contact network: supplied by the recorder.
struct RecordInputs {
    std::int64_t step = 0;       ///< [-]
    double time = 0;             ///< [s]
    double eps1 = 0;             ///< axial strain, compression positive [-]
    double eps2 = 0;             ///< lateral strain [-]
    double epsv = 0;             ///< volumetric strain (A0 - A) / A0 [-]
    double dilatancyIndex = 0;   ///< DI = -d eps_v / d eps_1 [-]
    Stress stress;               ///< sigma11, sigma22, sigma12 [Pa]
    double initialVoidCount = 0; ///< N_vi (N_v at eps1 = 0 of the test); <= 0: unknown [-]
    double strainRate1 = 0;      ///< compressive strain rate along x1 [1/s]
    double strainRate2 = 0;      ///< compressive strain rate along x2 [1/s]
    double meanDiameter = 0;     ///< d of the inertial number; <= 0 takes MeasureSet's [m]
    double density = 2650;       ///< grain density [kg/m^3]
    Energies energies;           ///< E_kin, E_elastic, W_friction, W_damping [J]
};

/// The numeric values of one record, in the order of seriesColumns() with `stage` left out
/// (size seriesColumns().size() - 1): the writer inserts the stage name at its position.
/// Nv_over_Nvi is 0 while N_vi is unknown.
std::vector<double> seriesRow(const MeasureSet& measures, const RecordInputs& inputs);

} // namespace grainlab
