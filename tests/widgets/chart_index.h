#pragma once
// The charts panel's chart of a given name, for the widget tests and the window tests.
#include <QString>

#include "grainlab/ui/charts_panel.h"

namespace grainlab::testing {

/// The index of the chart named `name` (its definition's name) in `panel`; -1 when none is.
inline int chartIndex(const ui::ChartsPanel& panel, const QString& name) {
    for (int k = 0; k < panel.chartCount(); ++k) {
        if (panel.definition(k).name == name) {
            return k;
        }
    }
    return -1;
}

} // namespace grainlab::testing
