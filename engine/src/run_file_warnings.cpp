// The run's warnings in the run file (docs/formats.md, "Warnings"): the group /warnings, one
// entry per warning in five datasets, rewritten whole when a warning is added.
#include <stdexcept>
#include <string>
#include <vector>

#include "grainlab/run_warning.h"
#include "run_file_io.h"

namespace grainlab::hdf5io {

namespace {
constexpr const char* kGroup = "warnings";
constexpr const char* kScratch = "warnings.writing";
} // namespace

void writeWarnings(H5::Group& root, const std::vector<RunWarning>& all) {
    if (root.nameExists(kScratch)) {
        root.unlink(kScratch); // left over from a run killed while writing
    }
    std::vector<std::string> kind, test, text;
    std::vector<std::int64_t> step;
    std::vector<double> strain;
    for (const RunWarning& w : all) {
        kind.push_back(w.kind);
        test.push_back(w.test);
        text.push_back(w.text);
        step.push_back(w.step);
        strain.push_back(w.axialStrain);
    }
    {
        H5::Group g = root.createGroup(kScratch);
        writeStringArray(g, "kind", kind);
        writeStringArray(g, "test", test);
        writeArray(g, "step", step, "-");
        writeArray(g, "axial_strain", strain, "-");
        writeStringArray(g, "text", text);
    }
    // The complete list replaces the older one only now.
    if (root.nameExists(kGroup)) {
        root.unlink(kGroup);
    }
    root.moveLink(kScratch, kGroup);
}

std::vector<RunWarning> readWarnings(const H5::Group& root) {
    std::vector<RunWarning> out;
    if (!root.nameExists(kGroup)) {
        return out;
    }
    const H5::Group g = root.openGroup(kGroup);
    const auto texts = [&](const char* name) {
        return readStringArray(g.openDataSet(name), std::string("dataset /warnings/") + name);
    };
    const std::vector<std::string> kind = texts("kind"), test = texts("test"), text = texts("text");
    const auto step = readArray<std::int64_t>(g, "step");
    const auto strain = readArray<double>(g, "axial_strain");
    const std::size_t n = kind.size();
    if (test.size() != n || text.size() != n || step.size() != n || strain.size() != n) {
        throw std::runtime_error("the datasets of /warnings differ in length");
    }
    for (std::size_t k = 0; k < n; ++k) {
        out.push_back({kind[k], test[k], step[k], strain[k], text[k]});
    }
    return out;
}

} // namespace grainlab::hdf5io
