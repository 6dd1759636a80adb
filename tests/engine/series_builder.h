#pragma once
// Hand-built test series with every recorded column (zeros unless set), for tests of what is
// computed from series: the metrics of a shear test, study summaries.
#include <string>
#include <vector>

#include "grainlab/measures.h"
#include "grainlab/series.h"

namespace grainlab::test {

struct SeriesBuilder {
    SeriesTable t;
    explicit SeriesBuilder(std::string test = "p100kPa") {
        t.test = std::move(test);
        for (const SeriesColumn& c : seriesColumns()) {
            if (!c.text) {
                t.columns.push_back(c);
            }
        }
    }
    /// A new row of stage `stage`, all zeros.
    std::vector<double>& row(const std::string& stage) {
        t.rows.emplace_back(t.columns.size(), 0.0);
        t.stages.push_back(stage);
        return t.rows.back();
    }
    double& at(std::vector<double>& r, const char* name) { return r[std::size_t(t.column(name))]; }
};

} // namespace grainlab::test
