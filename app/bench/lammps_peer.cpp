// See lammps_peer.h.
#include "bench/lammps_peer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "grainlab/oval_shape.h"

namespace grainlab {
namespace {

std::string shellQuote(const std::string& text) {
    std::string out = "'";
    for (char c : text) {
        out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return out + "'";
}

} // namespace

bool haveExecutable(const std::string& name) {
    return std::system(fmt::format("command -v {} >/dev/null 2>&1", shellQuote(name)).c_str()) == 0;
}

LammpsResult runLammps(const std::string& directory, const std::string& executable,
                       std::int64_t steps) {
    const std::string command =
        fmt::format("cd {} && OMP_NUM_THREADS=1 {} -in in.bench -var mode biax -var nsteps {} "
                    "-log none -echo none 2>&1",
                    shellQuote(directory), shellQuote(executable), steps);
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    if (!pipe) {
        throw std::runtime_error("bench: could not start LAMMPS: " + command);
    }
    std::string output;
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe.get()) != nullptr) {
        output += buffer;
    }
    LammpsResult r;
    double loop = 0;
    long long atoms = 0, ranSteps = 0;
    int procs = 0;
    // The last loop time is the timed run's (in.bench first does a `run 0`).
    const auto at = output.rfind("Loop time of ");
    if (at == std::string::npos ||
        std::sscanf(output.c_str() + at, "Loop time of %lf on %d procs for %lld steps with %lld",
                    &loop, &procs, &ranSteps, &atoms) != 4 ||
        !(loop > 0)) {
        throw std::runtime_error("bench: LAMMPS printed no loop time; its output ends with:\n" +
                                 output.substr(output.size() > 2000 ? output.size() - 2000 : 0));
    }
    r.grainStepsPerSecond = double(atoms) * double(ranSteps) / loop;
    const auto end = output.find("END: ");
    const auto z = end == std::string::npos ? end : output.find(" Z=", end);
    if (z != std::string::npos) {
        r.contactsPerGrain = std::atof(output.c_str() + z + 3);
    }
    return r;
}

SimulationState readLammpsDisks(const std::string& path, const SimulationParameters& parameters) {
    std::ifstream in(path);
    if (!in) {
        throw std::runtime_error(fmt::format("{}: cannot open the LAMMPS data file", path));
    }
    const auto fail = [&](int line, const std::string& what) {
        return std::runtime_error(fmt::format("{}:{}: {}", path, line, what));
    };
    long long atoms = -1;
    double xlo = 0, xhi = 0, ylo = 0, yhi = 0;
    bool haveX = false, haveY = false;
    struct Atom {
        long long id;
        double diameter, density, x, y;
    };
    std::vector<Atom> list;
    std::map<long long, std::size_t> byId;
    std::map<long long, std::array<double, 3>> velocities; // vx, vy, wz
    std::string line, section;
    int number = 0;
    std::getline(in, line); // the first line is a title
    ++number;
    while (std::getline(in, line)) {
        ++number;
        const auto hash = line.find('#');
        const std::string body = line.substr(0, hash);
        std::istringstream words(body);
        std::string first;
        if (!(words >> first)) {
            continue;
        }
        if (std::isalpha(static_cast<unsigned char>(first[0]))) {
            section = first; // "Atoms", "Velocities", ...
            if (section == "Atoms" && line.find("sphere") == std::string::npos) {
                throw fail(number, "the Atoms section must be atom_style sphere");
            }
            continue;
        }
        if (section.empty()) {
            std::istringstream header(body);
            double a = 0, b = 0;
            std::string k1, k2;
            header >> a;
            if (body.find("atoms") != std::string::npos) {
                atoms = static_cast<long long>(a);
            } else if (header >> b >> k1 >> k2; k1 == "xlo") {
                xlo = a, xhi = b, haveX = true;
            } else if (k1 == "ylo") {
                ylo = a, yhi = b, haveY = true;
            } else if (body.find("xy") != std::string::npos) {
                throw fail(number, "a triclinic box is not supported");
            }
            continue;
        }
        std::istringstream row(body);
        if (section == "Atoms") {
            Atom a{};
            int type = 0;
            if (!(row >> a.id >> type >> a.diameter >> a.density >> a.x >> a.y)) {
                throw fail(number, "expected: id type diameter density x y z ix iy iz");
            }
            if (!(a.diameter > 0.0)) {
                throw fail(number, fmt::format("diameter {} m: must be > 0", a.diameter));
            }
            byId[a.id] = list.size();
            list.push_back(a);
        } else if (section == "Velocities") {
            long long id = 0;
            double vx = 0, vy = 0, vz = 0, wx = 0, wy = 0, wz = 0;
            if (!(row >> id >> vx >> vy >> vz >> wx >> wy >> wz)) {
                throw fail(number, "expected: id vx vy vz wx wy wz");
            }
            velocities[id] = {vx, vy, wz};
        }
    }
    if (atoms < 1 || !haveX || !haveY) {
        throw std::runtime_error(
            fmt::format("{}: the header must give the atom count, xlo xhi and ylo yhi", path));
    }
    if (static_cast<long long>(list.size()) != atoms) {
        throw std::runtime_error(fmt::format("{}: the header announces {} atoms, the Atoms "
                                             "section holds {}",
                                             path, atoms, list.size()));
    }
    SimulationState s;
    s.parameters = parameters;
    // Size classes: one shape per distinct diameter (equal to round-off).
    std::vector<double> diameters;
    for (const Atom& a : list) {
        diameters.push_back(a.diameter);
    }
    std::sort(diameters.begin(), diameters.end());
    std::vector<double> classes;
    for (double d : diameters) {
        if (classes.empty() || d > classes.back() * (1 + 1e-9)) {
            classes.push_back(d);
            s.shapes.push_back(makeOval(d, 1.0));
        }
    }
    const double ly = yhi - ylo, lx = xhi - xlo;
    s.cell = {ly, 0.0, 0.0, lx};
    s.grains.resize(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) {
        const Atom& a = list[i];
        const auto c = std::lower_bound(classes.begin(), classes.end(), a.diameter * (1 - 1e-9));
        s.grains.shape[i] = static_cast<std::int32_t>(c - classes.begin());
        // LAMMPS stores the mass as density * 4/3 pi r^3; in.prep set it to 2650 pi r^2.
        const double r = 0.5 * a.diameter;
        const double mass = a.density * 4.0 / 3.0 * std::numbers::pi * r * r * r;
        const double ours = parameters.density * std::numbers::pi * r * r;
        if (std::fabs(mass - ours) > 1e-9 * ours) {
            throw std::runtime_error(fmt::format(
                "{}: atom {}: mass {:.9g} kg differs from density * pi r^2 = {:.9g} kg (a 2D "
                "mass per metre of thickness, `set density/disc` in LAMMPS, is expected)",
                path, a.id, mass, ours));
        }
        s.grains.x1[i] = a.y - ylo;
        s.grains.x2[i] = a.x - xlo;
        if (const auto v = velocities.find(a.id); v != velocities.end()) {
            s.grains.v1[i] = v->second[1];
            s.grains.v2[i] = v->second[0];
            s.grains.omega[i] = -v->second[2]; // swapping the axes mirrors the sense of rotation
        }
    }
    return s;
}

} // namespace grainlab
