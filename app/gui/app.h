#pragma once
// The desktop window's entry point, called by the command line (`grainlab` with no arguments or
// with an experiment file). Creates the QApplication and runs its event loop on the main thread.

#include <string>

namespace grainlab {

/// Opens the main window with `experimentPath` loaded (the quick experiment when empty) and
/// returns the application's exit code.
int runGui(int argc, char** argv, const std::string& experimentPath);

} // namespace grainlab
