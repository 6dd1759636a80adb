// See window_run_folder.h.
#include "gui/window_run_folder.h"

#include <filesystem>
#include <stdexcept>
#include <system_error>

#include <QDir>
#include <QRegularExpression>

#include <fmt/format.h>

namespace grainlab::ui {

namespace fs = std::filesystem;

QString defaultRunsFolder() {
    const QString fromEnvironment = qEnvironmentVariable("GRAINLAB_RUNS_DIR");
    if (!fromEnvironment.isEmpty()) {
        return QDir::cleanPath(fromEnvironment);
    }
    return QDir(QDir::homePath()).filePath(QStringLiteral("GrainLab runs"));
}

QString datedRunFolder(const QString& runsFolder, const QString& experimentName,
                       const QDateTime& when) {
    QString name = experimentName.trimmed();
    name.replace(QRegularExpression(QStringLiteral("[/\\\\:*?\"<>|\\x00-\\x1f]")),
                 QStringLiteral("_"));
    const QString stamp = when.toString(QStringLiteral("yyyy-MM-dd HH-mm-ss"));
    return QDir(runsFolder).filePath(name.isEmpty() ? stamp : stamp + QLatin1Char(' ') + name);
}

namespace {

/// True when this call created `folder`; false when it existed already.
bool createNew(const fs::path& folder) {
    std::error_code error;
    if (!folder.parent_path().empty()) {
        fs::create_directories(folder.parent_path(), error);
        if (error) {
            throw std::runtime_error(fmt::format("cannot create the runs folder {}: {}",
                                                 folder.parent_path().string(), error.message()));
        }
    }
    const bool created = fs::create_directory(folder, error);
    if (error) {
        throw std::runtime_error(
            fmt::format("cannot create the run folder {}: {}", folder.string(), error.message()));
    }
    return created;
}

} // namespace

std::string claimRunFolder(const std::string& folder, bool pickFreeName) {
    const fs::path wanted(folder);
    if (pickFreeName) {
        constexpr int kMaxTries = 1000;
        for (int n = 1; n <= kMaxTries; ++n) {
            const fs::path candidate =
                n == 1 ? wanted : fs::path(fmt::format("{} ({})", wanted.string(), n));
            if (createNew(candidate)) {
                return candidate.string();
            }
        }
        throw std::runtime_error(
            fmt::format("no free run folder name beside {} ({} tried)", folder, kMaxTries));
    }
    if (!createNew(wanted)) {
        std::error_code error;
        if (!fs::is_directory(wanted, error)) {
            throw std::runtime_error(
                fmt::format("the run folder {} exists and is not a folder", folder));
        }
        if (!fs::is_empty(wanted, error) || error) {
            throw std::runtime_error(fmt::format(
                "the run folder {} is not empty: a run there is never overwritten. Pick an empty "
                "or new folder; to continue a run recorded there: grainlab run --resume \"{}\"",
                folder, folder));
        }
    }
    return wanted.string();
}

} // namespace grainlab::ui
