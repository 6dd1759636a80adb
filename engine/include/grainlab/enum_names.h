#pragma once
// Enumerations written as words (run files, cell results, tables, the Python module): one table
// of (value, name) pairs per enumeration, read in both directions, instead of a switch to write
// the name and a chain of comparisons to read it back.

#include <cstddef>
#include <optional>
#include <string_view>

#include "grainlab/simulation_state.h"

namespace grainlab {

template <class Enum>
struct EnumName {
    Enum value;
    const char* name;
};

/// The name of `value` in `table`, or `fallback` when the table has none.
template <class Enum, std::size_t N>
constexpr const char* enumName(const EnumName<Enum> (&table)[N], Enum value, const char* fallback) {
    for (const EnumName<Enum>& e : table) {
        if (e.value == value) {
            return e.name;
        }
    }
    return fallback;
}

/// The value named `name` in `table`, or none.
template <class Enum, std::size_t N>
constexpr std::optional<Enum> enumFromName(const EnumName<Enum> (&table)[N],
                                           std::string_view name) {
    for (const EnumName<Enum>& e : table) {
        if (name == e.name) {
            return e.value;
        }
    }
    return std::nullopt;
}

/// How an axis is driven, as the run file and the Python module name it.
inline constexpr EnumName<AxisMode> kAxisModeNames[] = {{AxisMode::Strain, "strain"},
                                                        {AxisMode::Stress, "stress"},
                                                        {AxisMode::ConstantArea, "constant_area"},
                                                        {AxisMode::StressPath, "stress_path"}};

} // namespace grainlab
