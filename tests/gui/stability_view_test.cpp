// The Stability view (the Study window's Stability tab) on maps of the tiny stability preset
// (resources/stability/tiny.json: 4 cells, η ∈ {1, 0.6} × {gas, dense 15 kPa}) made by the real
// grainlab executable: each square of the heat map is painted in the colour of its cell's limit
// as the cell's JSON states it (read here independently of the engine's reader), choosing other
// axes changes the picture to the smallest over the axis left out, hovering and clicking a square
// shows the cell's numbers; folders holding something else are refused with the reason; a map
// started from the window runs to the end and fills in, a stopped or partial one continues, and a
// failing map shows its error. The tiny map runs once for the binary (a few seconds). With
// GRAINLAB_WRITE_SCREENSHOTS=1 the last test also writes docs/images/stability-view.png.
#include <cmath>
#include <map>

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QProcess>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grainlab/ui/colour_maps.h"
#include "grainlab/ui/heat_map_view.h"
#include "gui/main_window.h"
#include "gui/stability_view.h"
#include "gui/study_window.h"
#include "window_test_support.h"

namespace grainlab::ui {
namespace {

using window_tests::waitFor;

const QString kExe = QStringLiteral(GRAINLAB_EXE);
const QColor kNoData(220, 220, 220); // the painter's fill of a square without a value

/// One cell of a map as its cells/<id>.json says, read with nlohmann::json (not the engine).
struct CellJson {
    QString id;
    double aspectRatio = 0;
    std::string packing;
    nlohmann::json j;
};

std::vector<CellJson> readCells(const QString& folder) {
    std::vector<CellJson> out;
    for (const QFileInfo& f : QDir(QDir(folder).filePath("cells"))
                                  .entryInfoList({QStringLiteral("*.json")}, QDir::Files)) {
        QFile file(f.absoluteFilePath());
        EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << f.absoluteFilePath().toStdString();
        CellJson c;
        c.j = nlohmann::json::parse(file.readAll().toStdString());
        c.id = f.completeBaseName();
        c.aspectRatio = c.j.at("aspect_ratio").get<double>();
        c.packing = c.j.at("packing").get<std::string>();
        out.push_back(std::move(c));
    }
    return out;
}

/// The tiny map's square of a cell over (aspect ratio, packing): the preset lists η = 1 then
/// 0.6, and the gas then the dense state.
QPoint squareOf(const CellJson& c) {
    return {c.aspectRatio == 1.0 ? 0 : 1, c.packing == "gas" ? 0 : 1};
}

/// The tiny preset's map, made once by `grainlab stability --preset tiny --out DIR`.
QString tinyMap() {
    static QTemporaryDir dir;
    static QString folder;
    if (folder.isEmpty()) {
        QProcess p;
        p.setProcessChannelMode(QProcess::MergedChannels);
        p.start(kExe,
                {QStringLiteral("stability"), QStringLiteral("--preset"), QStringLiteral("tiny"),
                 QStringLiteral("--out"), dir.filePath("tiny"), QStringLiteral("--quiet")});
        const bool ended = p.waitForFinished(600000);
        EXPECT_TRUE(ended && p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0)
            << p.readAll().toStdString();
        folder = dir.filePath("tiny");
    }
    return folder;
}

bool near(QColor a, QColor b, int tolerance = 3) {
    return std::abs(a.red() - b.red()) <= tolerance &&
           std::abs(a.green() - b.green()) <= tolerance &&
           std::abs(a.blue() - b.blue()) <= tolerance;
}

/// A pixel of square `s` clear of its white border and of its centred text.
QColor fillOf(StabilityView& v, const QImage& image, QPoint s) {
    const QRectF r = v.heatMap()->map().cellRect(s.x(), s.y(), v.heatMap()->mapRect());
    return image.pixelColor((r.topLeft() + QPointF(8, 8)).toPoint());
}

/// Waits until the view has read a map with `cells` finished cells.
bool waitForCells(const StabilityView& v, int cells) {
    return waitFor(
        [&] {
            return v.folderState() && v.folderState()->kind == StabilityFolder::Kind::Map &&
                   v.folderState()->finishedCount() == cells;
        },
        30000);
}

/// Shows `v` at 1100 x 650 and opens the map folder `folder`, waiting until `cells` of its cells
/// are shown done. Call it within ASSERT_NO_FATAL_FAILURE.
void showMapFolder(StabilityView& v, const QString& folder, int cells) {
    v.resize(1100, 650);
    v.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&v));
    v.setMapFolder(folder);
    ASSERT_TRUE(waitForCells(v, cells));
}

QString number(double v) {
    return QString::number(v, 'g', 4);
}

void writeFile(const QString& path, const QByteArray& text) {
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly)) << path.toStdString();
    f.write(text);
}

QByteArray fileBytes(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

TEST(StabilityView, PaintsEachSquareInTheColourOfItsCellsLimit) {
    const QString folder = tinyMap();
    const std::vector<CellJson> cells = readCells(folder);
    ASSERT_EQ(cells.size(), 4u);
    StabilityView v(nullptr, kExe);
    ASSERT_NO_FATAL_FAILURE(showMapFolder(v, folder, 4));
    EXPECT_EQ(v.preset(), QString()); // Start would continue the folder's own map
    EXPECT_EQ(v.progressBar()->value(), 4);
    EXPECT_EQ(v.progressBar()->maximum(), 4);
    // The two axes with more than one value: η across, the packing state up.
    EXPECT_EQ(v.xAxis(), StabilityAxis::AspectRatio);
    EXPECT_EQ(v.yAxis(), StabilityAxis::Packing);
    QTest::qWait(20);

    // Each square in the colour of its cell's limit on the map's scale (lowest limit at one end
    // of the colour map, highest at the other).
    double lo = INFINITY, hi = -INFINITY;
    for (const CellJson& c : cells) {
        lo = std::min(lo, c.j.at("limit").get<double>());
        hi = std::max(hi, c.j.at("limit").get<double>());
    }
    ASSERT_GT(hi, 1.2 * lo) << "the tiny map's limits should differ (gas against dense)";
    const HeatMapPainter& map = v.heatMap()->map();
    ASSERT_EQ(map.xLabels.size(), 2);
    ASSERT_EQ(map.yLabels.size(), 2);
    const QImage image = v.heatMap()->grab().toImage();
    std::map<std::pair<int, int>, QColor> painted;
    for (const CellJson& c : cells) {
        const QPoint s = squareOf(c);
        const double limit = c.j.at("limit").get<double>();
        const QColor want = sequentialColour((limit - lo) / (hi - lo));
        const QColor got = fillOf(v, image, s);
        EXPECT_TRUE(near(got, want))
            << c.id.toStdString() << ": painted " << got.name().toStdString() << ", its limit "
            << limit << " is " << want.name().toStdString();
        painted[{s.x(), s.y()}] = got;
    }
    ASSERT_EQ(painted.size(), 4u);
    // The cells with the lowest and the highest limit, painted apart.
    const auto at = [&](double limit) {
        for (const CellJson& c : cells) {
            if (c.j.at("limit").get<double>() == limit) {
                const QPoint s = squareOf(c);
                return painted[{s.x(), s.y()}];
            }
        }
        return QColor();
    };
    EXPECT_FALSE(near(at(lo), at(hi), 30)) << at(lo).name().toStdString();

    // Other axes: stiffness ratio (one value) across, packing up; each square the smallest
    // limit over η, which is left out.
    const QImage before = image;
    v.xAxisBox()->setCurrentIndex(v.xAxisBox()->findData(int(StabilityAxis::StiffnessRatio)));
    QTest::qWait(20);
    EXPECT_EQ(v.xAxis(), StabilityAxis::StiffnessRatio);
    ASSERT_EQ(v.heatMap()->map().xLabels.size(), 1);
    ASSERT_EQ(v.heatMap()->map().yLabels.size(), 2);
    const QImage after = v.heatMap()->grab().toImage();
    EXPECT_NE(after, before);
    std::map<std::string, double> smallest;
    for (const CellJson& c : cells) {
        const double limit = c.j.at("limit").get<double>();
        smallest[c.packing] =
            smallest.count(c.packing) ? std::min(smallest[c.packing], limit) : limit;
    }
    const double lo2 = std::min(smallest["gas"], smallest["dense"]);
    const double hi2 = std::max(smallest["gas"], smallest["dense"]);
    ASSERT_GT(hi2, lo2);
    for (const auto& [packing, limit] : smallest) {
        const QPoint s(0, packing == "gas" ? 0 : 1);
        ASSERT_TRUE(v.heatMap()->map().values[std::size_t(s.y())].has_value());
        EXPECT_EQ(*v.heatMap()->map().values[std::size_t(s.y())], limit) << packing;
        EXPECT_TRUE(near(fillOf(v, after, s), sequentialColour((limit - lo2) / (hi2 - lo2))))
            << packing;
        // The square's details: the cell drawn (the smallest) first, the other one after it.
        const std::vector<int> inSquare = v.resultsInSquare(s);
        ASSERT_EQ(inSquare.size(), 2u) << packing;
        EXPECT_EQ(v.folderState()->results[std::size_t(inSquare[0])].limit.limit, limit);
    }
    // The same axis both ways is refused: the other box takes the axis just left.
    v.xAxisBox()->setCurrentIndex(v.xAxisBox()->findData(int(StabilityAxis::Packing)));
    EXPECT_EQ(v.xAxis(), StabilityAxis::Packing);
    EXPECT_EQ(v.yAxis(), StabilityAxis::StiffnessRatio);
    EXPECT_EQ(v.heatMap()->map().xLabels.size(), 2);
    EXPECT_EQ(v.heatMap()->map().yLabels.size(), 1);

    // The ratio limit / estimate, each square from its cell's JSON.
    v.setAxes(StabilityAxis::AspectRatio, StabilityAxis::Packing);
    v.valueBox()->setCurrentIndex(1);
    QTest::qWait(20);
    for (const CellJson& c : cells) {
        const QPoint s = squareOf(c);
        const auto& value = v.heatMap()->map().values[std::size_t(s.y() * 2 + s.x())];
        ASSERT_TRUE(value.has_value());
        EXPECT_DOUBLE_EQ(*value, c.j.at("limit").get<double>() / c.j.at("estimate").get<double>())
            << c.id.toStdString();
    }
}

TEST(StabilityView, HoveringOrClickingASquareShowsItsCellsNumbers) {
    const QString folder = tinyMap();
    const std::vector<CellJson> cells = readCells(folder);
    StabilityView v(nullptr, kExe);
    ASSERT_NO_FATAL_FAILURE(showMapFolder(v, folder, 4));
    QTest::qWait(20);
    for (const CellJson& c : cells) {
        const QPoint s = squareOf(c);
        const QPoint centre =
            v.heatMap()->map().cellRect(s.x(), s.y(), v.heatMap()->mapRect()).center().toPoint();
        QTest::mouseMove(v.heatMap(), centre);
        ASSERT_EQ(v.heatMap()->hoveredCell(), s) << c.id.toStdString();
        const QString text = v.details()->text();
        const nlohmann::json& j = c.j;
        const double limit = j.at("limit").get<double>(), estimate = j.at("estimate").get<double>();
        // Each number beside its name, as the panel words it.
        QStringList want{
            QStringLiteral("<b>%1</b>").arg(c.id),
            QStringLiteral("limit: <b>%1</b> √(m_min/k_n) = %2 s")
                .arg(number(limit), number(limit * j.at("time_unit").get<double>())),
            QStringLiteral("bracket: [%1, %2] · bracketed: %3")
                .arg(number(j.at("limit_low").get<double>()),
                     number(j.at("limit_high").get<double>()),
                     j.at("bracketed").get<bool>() ? "yes" : "no"),
            QStringLiteral(": %1 at step %2")
                .arg(QString::fromStdString(j.at("detector").get<std::string>()))
                .arg(j.at("detector_step").get<long long>()),
            QStringLiteral("estimate: %1 (translational %2, rotational %3)")
                .arg(number(estimate), number(j.at("estimate_translational").get<double>()),
                     number(j.at("estimate_rotational").get<double>())),
            QStringLiteral("limit / estimate: <b>%1</b>").arg(number(limit / estimate))};
        ASSERT_FALSE(j.at("accuracy").empty());
        for (const nlohmann::json& a : j.at("accuracy")) {
            want << QStringLiteral("%1 of the limit (Δt %2): max %3, final %4")
                        .arg(number(a.at("fraction").get<double>()),
                             number(a.at("step").get<double>()),
                             number(a.at("max_residual").get<double>()),
                             number(a.at("final_residual").get<double>()));
        }
        for (const QString& w : want) {
            EXPECT_TRUE(text.contains(w))
                << c.id.toStdString() << ": no " << w.toStdString() << " in " << text.toStdString();
        }
    }
    // A click keeps the square's numbers once the pointer leaves the map, and outlines it.
    const CellJson& chosen = cells.front();
    const QPoint s = squareOf(chosen);
    const QRectF r = v.heatMap()->map().cellRect(s.x(), s.y(), v.heatMap()->mapRect());
    const QImage unselected = v.heatMap()->grab().toImage();
    QTest::mouseClick(v.heatMap(), Qt::LeftButton, {}, r.center().toPoint());
    EXPECT_EQ(v.heatMap()->selectedCell(), s);
    QTest::mouseMove(v.heatMap(), QPoint(2, 2)); // the title's margin: no square
    EXPECT_EQ(v.heatMap()->hoveredCell(), QPoint(-1, -1));
    EXPECT_TRUE(v.details()->text().contains(QStringLiteral("<b>%1</b>").arg(chosen.id)))
        << v.details()->text().toStdString();
    const QImage selected = v.heatMap()->grab().toImage();
    const QPoint edge = (r.topLeft() + QPointF(r.width() / 2, 2.5)).toPoint(); // the outline
    EXPECT_TRUE(near(selected.pixelColor(edge), Qt::black, 20))
        << selected.pixelColor(edge).name().toStdString();
    EXPECT_TRUE(near(unselected.pixelColor(edge), fillOf(v, unselected, s)))
        << unselected.pixelColor(edge).name().toStdString(); // the square's own colour before
}

TEST(StabilityView, RefusesAFolderThatHoldsSomethingElseSayingWhy) {
    QTemporaryDir dir;
    StabilityView v(nullptr, kExe);
    const auto refusal = [&](const QString& folder) {
        v.setMapFolder(folder);
        EXPECT_TRUE(waitFor(
            [&] { return v.folderState() && v.folderState()->kind != StabilityFolder::Kind::New; },
            30000));
        EXPECT_EQ(int(v.folderState()->kind), int(StabilityFolder::Kind::Refused));
        EXPECT_FALSE(v.startButton()->isEnabled());
        EXPECT_TRUE(v.heatMap()->map().values.empty());
        QString error;
        EXPECT_FALSE(v.start(&error));
        EXPECT_FALSE(v.running());
        EXPECT_EQ(error, v.statusLabel()->text());
        return v.statusLabel()->text();
    };
    // Other files.
    const QString notes = dir.filePath("notes");
    ASSERT_TRUE(QDir().mkpath(notes));
    writeFile(QDir(notes).filePath("notes.txt"), "not a map");
    QString why = refusal(notes);
    EXPECT_TRUE(why.contains(notes) && why.contains("not a stability map folder") &&
                why.contains("no stability.json"))
        << why.toStdString();
    // A study folder: named as such.
    const QString study = dir.filePath("study");
    ASSERT_TRUE(QDir().mkpath(study));
    writeFile(QDir(study).filePath("study.json"), "{}");
    why = refusal(study);
    EXPECT_TRUE(why.contains("holds a study") && why.contains("Study tab")) << why.toStdString();
    // A stability.json the preset reader refuses: its reason, naming the file and the key.
    const QString bad = dir.filePath("bad");
    ASSERT_TRUE(QDir().mkpath(bad));
    writeFile(QDir(bad).filePath("stability.json"), R"({"axes": {"aspect_ratio": [5]}})");
    why = refusal(bad);
    EXPECT_TRUE(why.contains("stability.json") && why.contains("aspect_ratio"))
        << why.toStdString();
    // A new folder is not refused: Start would run the chosen preset into it.
    v.setMapFolder(dir.filePath("new"));
    ASSERT_TRUE(waitFor([&] { return v.folderState() != nullptr; }, 30000));
    EXPECT_EQ(int(v.folderState()->kind), int(StabilityFolder::Kind::New));
    EXPECT_EQ(v.preset(), QStringLiteral("tiny"));
    EXPECT_TRUE(v.startButton()->isEnabled());
    EXPECT_TRUE(v.statusLabel()->text().isEmpty()) << v.statusLabel()->text().toStdString();
    // An invalid preset file is refused at once, naming the file and the key.
    const QString badPreset = dir.filePath("bad-preset.json");
    writeFile(badPreset, R"({"axes": {"aspect_ratio": [1], "stiffness_ratio": [1],
                                     "damping": [{"kind": "none"}],
                                     "packing": [{"state": "liquid"}]}})");
    QString error;
    EXPECT_FALSE(v.choosePreset(badPreset, &error));
    EXPECT_TRUE(error.contains("bad-preset.json") && error.contains("state"))
        << error.toStdString();
    EXPECT_EQ(v.preset(), QStringLiteral("tiny"));
}

TEST(StabilityView, APartialMapContinuesOnStartAndFillsIn) {
    const QString source = tinyMap();
    QTemporaryDir dir;
    const QString folder = dir.filePath("partial");
    ASSERT_TRUE(QDir().mkpath(QDir(folder).filePath("cells")));
    ASSERT_TRUE(QFile::copy(QDir(source).filePath("stability.json"),
                            QDir(folder).filePath("stability.json")));
    // Two of the four cells done: the gas of disks and the dense ovals.
    const std::vector<CellJson> cells = readCells(source);
    std::vector<QString> kept;
    for (const CellJson& c : cells) {
        if (squareOf(c) == QPoint(0, 0) || squareOf(c) == QPoint(1, 1)) {
            const QString to = QDir(folder).filePath("cells/" + c.id + ".json");
            ASSERT_TRUE(QFile::copy(QDir(source).filePath("cells/" + c.id + ".json"), to));
            kept.push_back(to);
        }
    }
    ASSERT_EQ(kept.size(), 2u);
    std::map<QString, QByteArray> keptBytes;
    std::map<QString, QDateTime> keptTimes;
    for (const QString& f : kept) {
        keptBytes[f] = fileBytes(f);
        keptTimes[f] = QFileInfo(f).lastModified();
    }

    StabilityView v(nullptr, kExe);
    v.setPollInterval(100);
    ASSERT_NO_FATAL_FAILURE(showMapFolder(v, folder, 2));
    EXPECT_EQ(v.preset(), QString());
    EXPECT_EQ(v.progressBar()->value(), 2);
    QTest::qWait(20);
    QImage image = v.heatMap()->grab().toImage();
    for (const QPoint s : {QPoint(0, 0), QPoint(1, 1)}) {
        EXPECT_FALSE(near(fillOf(v, image, s), kNoData)) << s.x() << ", " << s.y();
    }
    for (const QPoint s : {QPoint(1, 0), QPoint(0, 1)}) {
        EXPECT_TRUE(near(fillOf(v, image, s), kNoData)) << s.x() << ", " << s.y();
    }

    QString error;
    ASSERT_TRUE(v.start(&error)) << error.toStdString();
    EXPECT_TRUE(v.statusLabel()->text().contains(QDir(folder).filePath("stability.json")))
        << v.statusLabel()->text().toStdString();
    ASSERT_TRUE(waitFor([&] { return !v.running(); }, 600000));
    ASSERT_EQ(v.lastExitStatus().value_or(-99), 0) << v.statusLabel()->text().toStdString();
    EXPECT_TRUE(v.statusLabel()->text().contains("4 of 4 cells done"))
        << v.statusLabel()->text().toStdString();
    ASSERT_TRUE(waitForCells(v, 4));
    EXPECT_EQ(v.progressBar()->value(), 4);
    for (const QString& f : kept) { // not redone
        EXPECT_EQ(fileBytes(f), keptBytes[f]) << f.toStdString();
        EXPECT_EQ(QFileInfo(f).lastModified(), keptTimes[f]) << f.toStdString();
    }
    QTest::qWait(20);
    image = v.heatMap()->grab().toImage();
    for (int x = 0; x < 2; ++x) {
        for (int y = 0; y < 2; ++y) {
            EXPECT_FALSE(near(fillOf(v, image, {x, y}), kNoData)) << x << ", " << y;
        }
    }
}

TEST(StabilityView, AFailingMapShowsItsErrorLines) {
    // The tiny map's folder, but Start given another preset: the command refuses the folder.
    QTemporaryDir dir;
    const QString folder = dir.filePath("map");
    ASSERT_TRUE(QDir().mkpath(folder));
    ASSERT_TRUE(QFile::copy(QStringLiteral(GRAINLAB_SOURCE_DIR "/resources/stability/tiny.json"),
                            QDir(folder).filePath("stability.json")));
    QByteArray other =
        fileBytes(QStringLiteral(GRAINLAB_SOURCE_DIR "/resources/stability/tiny.json"));
    other.replace("\"seed\": 1", "\"seed\": 2");
    ASSERT_TRUE(other.contains("\"seed\": 2"));
    const QString otherPreset = dir.filePath("other.json");
    writeFile(otherPreset, other);

    StabilityView v(nullptr, kExe);
    v.setMapFolder(folder);
    ASSERT_TRUE(waitForCells(v, 0));
    QString error;
    ASSERT_TRUE(v.choosePreset(otherPreset, &error)) << error.toStdString();
    EXPECT_EQ(v.folderPath(), folder); // a folder chosen by the user stays
    QSignalSpy ended(&v, &StabilityView::mapEnded);
    ASSERT_TRUE(v.start(&error)) << error.toStdString();
    ASSERT_TRUE(waitFor([&] { return !v.running(); }, 120000));
    EXPECT_EQ(v.lastExitStatus().value_or(-99), 1);
    ASSERT_EQ(ended.size(), 1);
    const QString status = v.statusLabel()->text();
    EXPECT_TRUE(status.contains("The map failed (exit status 1)") &&
                status.contains("grainlab: error:") && status.contains("holds a different map"))
        << status.toStdString();
    EXPECT_TRUE(QDir(QDir(folder).filePath("cells")).isEmpty());
}

TEST(StabilityView, TheTinyPresetStartedFromTheStudyWindowRunsToTheEnd) {
    MainWindow w;
    // File > Stability maps… shows the Study window at its Stability tab.
    QAction* menu = nullptr;
    for (QAction* a : w.menuBar()->findChildren<QAction*>()) {
        if (a->text() == QObject::tr("S&tability maps…")) {
            menu = a;
        }
    }
    ASSERT_NE(menu, nullptr);
    menu->trigger();
    StudyWindow* s = w.studyWindow();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(s));
    StabilityView* v = s->stabilityView();
    EXPECT_EQ(s->tabs()->currentWidget(), v);
    s->setExecutable(kExe);
    v->setPollInterval(100);
    s->resize(1100, 720);

    QTemporaryDir dir;
    const QString folder = dir.filePath("tiny");
    v->setMapFolder(folder);
    QString error;
    ASSERT_TRUE(v->choosePreset(QStringLiteral("tiny"), &error)) << error.toStdString();
    EXPECT_EQ(v->folderPath(), folder);
    ASSERT_TRUE(waitFor([&] { return v->folderState() != nullptr; }, 30000));
    EXPECT_EQ(int(v->folderState()->kind), int(StabilityFolder::Kind::New));
    EXPECT_EQ(v->progressBar()->maximum(), 4);

    // Start, then Stop once a cell has finished: the map ends and keeps its cells.
    ASSERT_TRUE(v->start(&error)) << error.toStdString();
    EXPECT_TRUE(v->running());
    EXPECT_FALSE(v->startButton()->isEnabled());
    EXPECT_TRUE(v->stopButton()->isEnabled());
    EXPECT_FALSE(v->presetBox()->isEnabled());
    ASSERT_TRUE(waitFor(
        [&] {
            return !v->running() || (v->folderState() && v->folderState()->finishedCount() >= 1);
        },
        300000));
    if (v->running() && v->folderState()->finishedCount() < 4) {
        v->stop();
        ASSERT_TRUE(waitFor([&] { return !v->running(); }, 120000));
        if (v->lastExitStatus().value_or(-99) != 0) { // else it ended before the signal
            EXPECT_EQ(v->lastExitStatus().value_or(-99), 130);
            EXPECT_TRUE(v->statusLabel()->text().startsWith("Stopped"))
                << v->statusLabel()->text().toStdString();
        }
    }
    ASSERT_TRUE(waitFor([&] { return !v->running(); }, 600000));

    // Start again (or the first time, had it ended): it runs to the end and the map fills in.
    ASSERT_TRUE(v->start(&error)) << error.toStdString();
    ASSERT_TRUE(waitFor([&] { return !v->running(); }, 600000));
    ASSERT_EQ(v->lastExitStatus().value_or(-99), 0) << v->statusLabel()->text().toStdString();
    ASSERT_TRUE(waitForCells(*v, 4));
    EXPECT_EQ(v->progressBar()->value(), 4);
    EXPECT_TRUE(v->progressLabel()->text().startsWith("4 of 4 cells finished"))
        << v->progressLabel()->text().toStdString();
    EXPECT_TRUE(QFileInfo::exists(QDir(folder).filePath("limits.csv")));
    QTest::qWait(50);
    const QImage image = v->heatMap()->grab().toImage();
    for (int x = 0; x < 2; ++x) {
        for (int y = 0; y < 2; ++y) {
            EXPECT_FALSE(near(fillOf(*v, image, {x, y}), kNoData)) << x << ", " << y;
        }
    }

    if (qEnvironmentVariable("GRAINLAB_WRITE_SCREENSHOTS") != QLatin1String("1")) {
        GTEST_SKIP() << "set GRAINLAB_WRITE_SCREENSHOTS=1 to write docs/images/";
    }
    // The user guide's picture: the dense ovals' square chosen, its numbers beside the map.
    const QRectF r = v->heatMap()->map().cellRect(1, 1, v->heatMap()->mapRect());
    QTest::mouseClick(v->heatMap(), Qt::LeftButton, {}, r.center().toPoint());
    QTest::mouseMove(v->heatMap(), QPoint(2, 2));
    QTest::qWait(50);
    const QDir images(QStringLiteral(GRAINLAB_SOURCE_DIR "/docs/images"));
    ASSERT_TRUE(QDir().mkpath(images.path()));
    EXPECT_TRUE(s->grab().save(images.filePath(QStringLiteral("stability-view.png"))));
}

} // namespace
} // namespace grainlab::ui
