// Placeholder until the scene view lands (issue 5); keeps the widgets library non-empty.
namespace grainlab::ui {
int widgetsLibraryVersion() { return 1; }
} // namespace grainlab::ui
