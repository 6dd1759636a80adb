#pragma once
// A strict reader for the project's JSON input files (experiment files now, study files next):
// parses JSON refusing duplicate keys, excessive nesting and out-of-range numbers, and reads it
// through sections that know their keys, so that every refusal names the file, the dotted key
// path, the value and the allowed range or type. An unknown key is refused with the nearest
// known key suggested. Nothing is guessed or clamped. Value types and pure functions, used on
// the caller's thread; safe on any thread.
//
// A schema reads like this:
//     const Json root = parseStrictJson(readInputFile(path, "experiment file"), path);
//     const JsonSection top(path, root, "", {"grains", "seed"});
//     const JsonSection grains = top.child("grains", {"count"}, true);
//     const std::int64_t count = grains.integer("count", 1, 1000, std::nullopt);

#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace grainlab {

using Json = nlohmann::json;

/// A refused input file. what() reads like
/// `reference.json: grains.aspect_ratio = 1.5: must be a number in (0, 1]`.
class JsonFileError : public std::runtime_error {
public:
    JsonFileError(std::string file, std::string keyPath, const std::string& message);
    std::string file;    ///< the file (or source name) at fault
    std::string keyPath; ///< dotted key path, e.g. "grains.aspect_ratio" ("" for the whole file)
};

/// Deepest nesting of objects and arrays a file may have (the experiment file needs 3).
inline constexpr int kMaxJsonNesting = 32;

/// Parses JSON text, refusing duplicate keys (nlohmann keeps the last one silently), nesting
/// deeper than kMaxJsonNesting, and numbers beyond the range of a double (naming their key).
/// `file` names the text in errors.
Json parseStrictJson(const std::string& text, const std::string& file);

/// The whole text of the file at `path`; refuses a folder, a file that cannot be opened and a
/// read error, naming the file. `what` names the kind of file ("experiment file").
std::string readInputFile(const std::string& path, const std::string& what);

/// An interval of allowed real values; infinite ends mean unbounded.
struct Range {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool loClosed = false;
    bool hiClosed = false;

    bool contains(double v) const;
    /// "> 0", "in (0, 1]", ...
    std::string text() const;
};

Range positive();                       ///< (0, inf)
Range nonNegative();                    ///< [0, inf)
Range openClosed(double lo, double hi); ///< (lo, hi]
Range open(double lo, double hi);       ///< (lo, hi)
Range closed(double lo, double hi);     ///< [lo, hi]

/// "parent.key", or "key" at the top level.
std::string joinPath(const std::string& parent, const std::string& key);
/// The value as written in JSON, shortened for messages.
std::string showValue(const Json& v);
/// "a string", "an object", ... for messages.
std::string jsonTypeName(const Json& v);

/// One JSON object of a file with its key path and the keys it may hold. Refuses a non-object
/// and unknown keys when built. Every getter names the file, the key path, the value and the
/// allowed range when it refuses (JsonFileError). Holds references to the file name and the
/// node: both must outlive it.
class JsonSection {
public:
    JsonSection(const std::string& file, const Json& node, std::string path,
                std::vector<std::string> known);

    const std::string& path() const { return path_; }
    std::string path(const std::string& key) const { return joinPath(path_, key); }
    bool has(const std::string& key) const { return node_.contains(key); }
    const Json& at(const std::string& key) const { return node_.at(key); }

    /// Throws JsonFileError for `key` with `message`.
    [[noreturn]] void fail(const std::string& key, const std::string& message) const;
    /// "key = value: must be <allowed>".
    [[noreturn]] void refuse(const std::string& key, const Json& value,
                             const std::string& allowed) const;
    /// "missing required key key (<allowed>)".
    [[noreturn]] void missing(const std::string& key, const std::string& allowed) const;

    /// A finite real number in `range`; `fallback` is the default, none means required.
    double number(const std::string& key, Range range, std::optional<double> fallback) const;
    /// An integer in [lo, hi]; an exactly integral real such as 2e6 is accepted.
    std::int64_t integer(const std::string& key, std::int64_t lo, std::int64_t hi,
                         std::optional<std::int64_t> fallback) const;
    /// One of `allowed` (strings).
    std::string choice(const std::string& key, const std::vector<std::string>& allowed,
                       std::optional<std::string> fallback) const;
    /// A non-empty string, or `fallback` when absent.
    std::string text(const std::string& key, const std::string& fallback) const;
    /// A non-empty array of finite real numbers, each in `range`; absent gives nullopt.
    std::optional<std::vector<double>> numbers(const std::string& key, Range range) const;
    /// A nested object; absent gives an empty section (all defaults) unless required.
    JsonSection child(const std::string& key, std::vector<std::string> known, bool required,
                      const std::string& requiredWhat = "an object") const;
    /// `key` as one object or a non-empty array of objects: a section for each (paths
    /// "key" or "key[i]"); empty when absent.
    std::vector<JsonSection> objects(const std::string& key,
                                     const std::vector<std::string>& known) const;

private:
    [[noreturn]] void refuseUnknown(const std::string& key) const;

    const std::string& file_;
    const Json& node_;
    std::string path_;
    std::vector<std::string> known_;
};

} // namespace grainlab
