#pragma once
// Parameter sweeps: many runs of one model with `--set` values taken from a
// grid or a Latin hypercube, on all cores (one Simbody system per worker,
// never shared), resumable, and shardable across machines.
//
// Each point's outcome is written as DIR/points/NNNNNN.json as soon as it
// finishes (atomically), so an interrupted sweep resumes where it stopped
// and `milldyn merge` can join the parts of a sharded one. The table
// DIR/sweep.csv is rebuilt from those files in point order, so it is the
// same byte for byte whatever the number of jobs or shards.

#include "driver/ModelFile.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace milldyn {

/// One swept key: its model-file path and the value text of every point
/// ("12.5 N*m"); `unit` is the unit the values were written in ("" for SI).
struct SweepAxis {
    std::string path;
    std::string unit;
    std::vector<double> values;  ///< in `unit`
    /// No unit given and the values are SI (the Python module's numbers);
    /// on the command line a dimensional axis needs its unit.
    bool bareNumberIsSI = false;
    /// Moves with the axis before it (paths tied with ';' in one --grid or
    /// --range): both take their value index together, one dimension of
    /// the sweep (two flywheels; a motor's synchronous and rated speed).
    bool tiedToPrevious = false;
};

/// The most points one sweep may have (grid or --lhs).
constexpr std::size_t kMaxSweepPoints = 1000000;

struct SweepPlan {
    std::vector<SweepAxis> axes;
    /// Number of points; point i takes axes[a].values[pointValue(i, a)].
    std::size_t count = 0;
    bool cartesian = true;  ///< grid (product of axes) or LHS (axes side by side)

    /// Index into axes[a].values of point i (tied axes share it).
    std::size_t valueIndex(std::size_t point, std::size_t axis) const;
    /// The --set overrides of point i.
    std::vector<Override> overrides(std::size_t point) const;
};

/// "path=a:b:n" → an axis of n evenly spaced values from a to b (units
/// allowed, the same on both ends; a bare 0 takes the other end's unit);
/// "path=a:b:n:log" → n values spaced evenly in log (a, b of one sign,
/// not 0); "path=v1,v2,..." → the values as listed (one unit for all).
/// Throws SpecError located at the option.
SweepAxis parseGrid(const std::string& text);
/// One --grid option: one axis, or several "path=spec;path=spec" tied to
/// one dimension (each after the first tiedToPrevious; equal counts).
std::vector<SweepAxis> parseGridAxes(const std::string& text);
/// "path=a:b" → a range for a Latin hypercube.
SweepAxis parseRange(const std::string& text);
/// One --range option: "path=a:b;path=c:d" ties ranges to one dimension
/// of the hypercube (the same stratum and position in each).
std::vector<SweepAxis> parseRangeAxes(const std::string& text);
/// Refuses a path swept twice (the first axis would never be used) and a
/// base override (--set, --end-time, ...) of a swept path (the sweep would
/// silently override it). Throws SpecError naming both.
void checkSweepPaths(const std::vector<SweepAxis>& axes, const std::vector<Override>& base = {});
/// n points of a Latin hypercube over the ranges (deterministic for a seed).
SweepPlan makeLatinHypercube(std::vector<SweepAxis> ranges, std::size_t n, unsigned long seed);
SweepPlan makeGrid(std::vector<SweepAxis> axes);

struct CancelFlag;

struct SweepOptions {
    std::string model;
    std::vector<Override> baseOverrides;  ///< the user's own --set
    unsigned jobs = 1;
    std::size_t shardIndex = 0, shardCount = 1;  ///< this process runs points with i % count == index
    std::string outDir;
    /// If set: another thread (Python's Ctrl-C) may set it; every running
    /// point stops at its next sample, no further point starts, and the
    /// sweep throws RunCancelled. Finished points stay (they resume); the
    /// table is not written.
    CancelFlag* cancel = nullptr;
};

/// The override paths that are no part of a sweep's identity (its digest):
/// outputs.plots and outputs.sweep_plots (a sweep's points draw nothing;
/// `--no-plots` and `--set outputs.plots=false` both only skip the
/// sweep_*.png, outputs.sweep_plots only chooses them).
bool isPresentationPath(const std::string& path);

struct SweepSummary {
    std::size_t run = 0, resumed = 0, failed = 0, total = 0;
    /// Points whose analysis did not run to its end (status failed or
    /// bad_input); a stalled or unfinished start is a verdict, not an error.
    std::size_t errors = 0;
    std::vector<std::string> files;
};

/// Runs (or resumes) the sweep and writes the table. `progress(done, total)`
/// is called from worker threads (serialised).
SweepSummary runSweep(const SweepPlan& plan, const SweepOptions& options,
                      const std::function<void(std::size_t, std::size_t, std::size_t)>& progress = {});

/// One shard's share of a sweep, without the table: its points (the text of
/// their point files) in point order. runSweep is runSweepPart followed by
/// writeSweepTable; the MPI mode gathers the parts of all ranks in between.
struct SweepPart {
    SweepSummary summary;            ///< run and resumed; total and failed are the table's
    std::vector<std::string> points;  ///< JSON text of each point file
};
SweepPart runSweepPart(const SweepPlan& plan, const SweepOptions& options,
                       const std::function<void(std::size_t, std::size_t, std::size_t)>& progress = {});

/// Writes DIR/sweep.csv from point-file texts (any order; sorted by index),
/// and, when `writePoints`, DIR/points/NNNNNN.json of each. Throws
/// OutputError, or SpecError when a text is not a point.
SweepSummary writeSweepTable(const std::string& outDir, const std::vector<std::string>& points,
                             SweepSummary summary, bool writePoints);

/// Joins the point files of several sweep directories into `outDir`.
SweepSummary mergeSweeps(const std::vector<std::string>& dirs, const std::string& outDir);

}  // namespace milldyn
