#pragma once

#include <string>

namespace grainlab {

/// What `grainlab --version` prints: the version and the commit the executable was built from,
/// e.g. "GrainLab 0.1.0 (commit 2a4de12f1c3b)"; "commit unknown" outside a git checkout, and
/// "-modified" after the commit when the checkout had changes not committed.
std::string versionText();

/// The commit alone, as in versionText().
std::string buildCommit();

} // namespace grainlab
