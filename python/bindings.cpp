// The C++ half of the Python module `milldyn` (python/milldyn/__init__.py is
// the other): thin pybind11 wrappers over driver/Api and the driver's public
// functions, the same code `milldyn run|info|sweep|validate` calls. Every
// run releases the GIL; a run on Python's main thread checks for signals
// (Ctrl-C) at its samples, and any run stops at its next sample when its
// CancelToken is set. C++ errors become the exceptions of milldyn.errors,
// carrying the text the CLI prints.

#include "driver/Api.h"
#include "driver/Front.h"
#include "driver/PluginLoader.h"
#include "driver/Simulation.h"
#include "driver/Sweep.h"
#include "driver/Units.h"
#include "driver/outputs/AtomicFile.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <tuple>

#include <chrono>
#include <cmath>
#include <memory>
#include <thread>

namespace py = pybind11;
using namespace milldyn;

namespace {

/// Raises milldyn.errors.NAME(args...) (called with the GIL held).
template <class... Args>
void raise(const char* name, Args&&... args) {
    py::object cls = py::module_::import("milldyn.errors").attr(name);
    py::object exc = cls(std::forward<Args>(args)...);
    PyErr_SetObject(cls.ptr(), exc.ptr());
}

void translate(std::exception_ptr p) {
    try {
        if (p) std::rethrow_exception(p);
    } catch (const SpecError& e) {
        raise("ModelError", e.formatted(), e.where().file, e.where().line, e.where().column, e.key(),
              std::string(e.what()), e.where().includedFrom);
    } catch (const AnalysisError& e) {
        raise("AnalysisFailed", std::string("milldyn: analysis failed: ") + e.what(), std::string(e.what()));
    } catch (const OutputError& e) {
        raise("OutputFailed", std::string("milldyn: output failed: ") + e.what(), std::string(e.what()));
    } catch (const RunCancelled& e) {
        raise("Cancelled", std::string(e.what()));
    } catch (const units::UnitError& e) {
        raise("UnitError", std::string(e.what()), static_cast<int>(e.column()));
    }
}

struct Token {
    std::shared_ptr<CancelFlag> flag = std::make_shared<CancelFlag>();
};

struct SpecHandle {
    ModelSpec spec;
};

struct RunHandle {
    ModelSpec spec;
    RunOutcome run;
};

/// (path, text, text is an SI number): milldyn._overrides' triples.
using OverrideTriples = std::vector<std::tuple<std::string, std::string, bool>>;

std::vector<Override> toOverrides(const OverrideTriples& triples) {
    std::vector<Override> out;
    for (const auto& [path, value, si] : triples) out.push_back({path, value, si});
    return out;
}

py::list columnsOf(const std::vector<std::vector<double>>& rows, std::size_t ncols) {
    py::list cols;
    for (std::size_t c = 0; c < ncols; ++c) {
        py::array_t<double> a(static_cast<py::ssize_t>(rows.size()));
        auto m = a.mutable_unchecked<1>();
        for (std::size_t r = 0; r < rows.size(); ++r) m(static_cast<py::ssize_t>(r)) = c < rows[r].size() ? rows[r][c] : 0.0;
        cols.append(a);
    }
    return cols;
}

py::dict tableDict(const std::string& name, const std::vector<std::string>& names,
                   const std::vector<std::string>& units, const std::vector<std::vector<double>>& rows) {
    py::dict d;
    d["name"] = name;
    d["names"] = names;
    d["units"] = units;
    d["columns"] = columnsOf(rows, names.size());
    return d;
}

py::list scalars(const std::vector<ResultScalar>& list) {
    py::list out;
    for (const auto& r : list) out.append(py::make_tuple(r.name, r.value, r.unit, r.doc));
    return out;
}

const char* kindName(ParamKind k) {
    switch (k) {
        case ParamKind::Quantity: return "quantity";
        case ParamKind::Choice: return "choice";
        case ParamKind::BodyRef: return "body";
        case ParamKind::BodyPair: return "body_pair";
        case ParamKind::BodyList: return "body_list";
        case ParamKind::QuantityList: return "quantity_list";
        case ParamKind::Text: return "text";
    }
    return "?";
}

py::dict schemaDict(const ElementSchema& s) {
    py::dict keys;
    for (const auto& p : s.params) {
        py::dict k;
        k["kind"] = isScheduleKey(p) ? "schedule" : kindName(p.kind);
        const bool numeric = p.kind == ParamKind::Quantity || p.kind == ParamKind::QuantityList;
        k["unit"] = numeric ? py::object(py::str(p.unit)) : py::object(py::none());
        k["required"] = p.required;
        if (p.defaultValue) k["default"] = *p.defaultValue;
        else if (!p.required && !numeric) k["default"] = p.defaultText;
        else k["default"] = py::none();
        k["choices"] = p.choices;
        k["min"] = p.min ? py::object(py::float_(*p.min)) : py::object(py::none());
        k["min_exclusive"] = p.minExclusive;
        k["max"] = p.max ? py::object(py::float_(*p.max)) : py::object(py::none());
        k["max_exclusive"] = p.maxExclusive;
        if (p.kind == ParamKind::BodyList || p.kind == ParamKind::QuantityList) {
            k["min_count"] = p.minCount;
            k["max_count"] = p.maxCount;
        }
        k["doc"] = p.doc;
        keys[py::str(p.key)] = k;
    }
    py::dict d;
    d["type"] = s.type;
    d["doc"] = s.doc;
    d["output_only"] = s.outputOnly;
    d["keys"] = keys;
    return d;
}

std::unique_ptr<RunHandle> runSpec(const SpecHandle& h, Token* token, bool checkSignals, bool checkRes) {
    auto flag = token ? token->flag : std::make_shared<CancelFlag>();
    ProgressFn signals;
    if (checkSignals) {
        // Ctrl-C on the main thread: Python's handler runs only when the
        // interpreter does, so look at most every 50 ms of wall time.
        auto last = std::make_shared<std::chrono::steady_clock::time_point>(std::chrono::steady_clock::now());
        signals = [last](double, double) {
            const auto now = std::chrono::steady_clock::now();
            if (now - *last < std::chrono::milliseconds(50)) return;
            *last = now;
            py::gil_scoped_acquire gil;
            if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        };
    }
    const ProgressFn progress = cancellableProgress(*flag, signals);
    auto out = std::make_unique<RunHandle>();
    out->spec = h.spec;
    py::gil_scoped_release release;
    out->run = runModel(out->spec, progress);
    if (checkRes) checkResolution(out->spec, out->run.result);  // `run --check-resolution` (driver/Front.h)
    return out;
}

}  // namespace

PYBIND11_MODULE(_milldyn, m) {
    m.doc() = "milldyn's C++ core (use the package milldyn)";
    py::register_exception_translator(&translate);
    m.attr("__version__") = milldynVersion();

    py::class_<Token>(m, "CancelToken", "Stops the runs it is given at their next sample, from any thread.")
        .def(py::init<>())
        .def("cancel", [](Token& t) { t.flag->cancelled = true; }, "Asks the run to stop.")
        .def_property_readonly("cancelled", [](const Token& t) { return t.flag->cancelled.load(); })
        .def_property_readonly("progress", [](const Token& t) {
            return py::make_tuple(t.flag->simulated.load(), t.flag->end.load());
        }, "(reached, of): the last progress a run reported (simulated time [s], or steps).");

    py::class_<SpecHandle>(m, "Spec")
        .def_property_readonly("name", [](const SpecHandle& h) { return h.spec.name; })
        .def_property_readonly("file", [](const SpecHandle& h) { return h.spec.file; })
        .def_property_readonly("description", [](const SpecHandle& h) { return h.spec.description; })
        .def_property_readonly("analysis", [](const SpecHandle& h) { return h.spec.scenario.type; });

    m.def("read_model", [](const std::string& path, const OverrideTriples& overrides) {
        auto h = std::make_unique<SpecHandle>();
        py::gil_scoped_release release;
        h->spec = readModel(path, toOverrides(overrides));
        return h;
    });

    m.def("describe", [](const SpecHandle& h) {
        ModelInfo i;
        {
            py::gil_scoped_release release;
            i = describeModel(h.spec);
        }
        py::dict d;
        d["name"] = i.name;
        d["file"] = i.file;
        d["bodies"] = i.bodies;
        d["mobilities"] = i.mobilities;
        d["constraints"] = i.constraints;
        d["forces"] = i.forces;
        py::list bodies;
        for (const auto& b : i.bodyList) {
            py::dict bd;
            bd["name"] = b.name;
            bd["joint"] = "pin";
            bd["parent"] = b.parent;
            bd["inertia"] = py::make_tuple(b.inertia, "kg*m^2");
            bodies.append(bd);
        }
        d["body_list"] = bodies;
        py::list elements;
        for (const auto& e : i.elements) elements.append(py::make_tuple(e.name, e.type));
        d["elements"] = elements;
        d["scenario"] = i.scenario;
        d["integrator"] = i.integrator;
        d["accuracy"] = i.accuracy;
        d["max_step"] = i.maxStep > 0 ? py::object(py::make_tuple(i.maxStep, "s")) : py::object(py::none());
        d["fidelity"] = i.fidelity.empty() ? py::object(py::none()) : py::object(py::str(i.fidelity));
        d["presets"] = i.presets;
        d["preset"] = i.preset.empty() ? py::object(py::none()) : py::object(py::make_tuple(i.preset, i.presetWhy));
        d["derived"] = scalars(i.derived);
        py::list built, notBuilt;
        for (const auto& n : i.built) built.append(py::make_tuple(n.what, n.why));
        for (const auto& n : i.notBuilt) notBuilt.append(py::make_tuple(n.what, n.why));
        d["built"] = built;
        d["not_built"] = notBuilt;
        d["time_integration"] = i.timeIntegration;
        py::list outputs;
        for (const auto& o : i.outputs) outputs.append(py::make_tuple(o.name, o.unit));
        d["outputs"] = outputs;
        d["warnings"] = i.warnings;  // as `milldyn info` prints them (a model without gravity, ...)
        d["notes"] = i.notes;        // what the reader did (an analysis switched by set, keys dropped)
        // What each element registered (issue 31): {element: (type, [(kind, name, shaft, detail)])}.
        py::dict contributions;
        for (const auto& r : i.contributions) {
            py::list items;
            for (const auto& c : r.contributions)
                items.append(py::make_tuple(contributionKindName(c.kind), c.name, c.shaft, c.detail));
            contributions[py::str(r.element)] = py::make_tuple(r.type, items);
        }
        d["contributions"] = contributions;
        return d;
    });

    m.def("run", &runSpec, py::arg("spec"), py::arg("token") = nullptr, py::arg("check_signals") = false,
          py::arg("check_resolution") = false);

    // `milldyn front` (driver/Front.h): the front as plain data; the
    // module's front() wraps it.
    m.def("front", [](const std::string& model, const OverrideTriples& overrides, const std::vector<std::string>& integrators,
                      const std::vector<double>& accuracies, const std::string& refIntegrator, double refAccuracy,
                      double budget, int repeat, bool writePresets) {
        FrontOptions o;
        if (!integrators.empty()) o.integrators = integrators;
        if (!accuracies.empty()) o.accuracies = accuracies;
        if (!refIntegrator.empty()) o.referenceIntegrator = refIntegrator;
        if (refAccuracy > 0) o.referenceAccuracy = refAccuracy;
        o.budget = budget;
        o.repeat = repeat;
        FrontResult f;
        {
            py::gil_scoped_release release;
            f = measureFront(model, toOverrides(overrides), o);
        }
        auto point = [](const FrontPoint& p) {
            py::dict d;
            d["integrator"] = p.integrator;
            d["accuracy"] = p.accuracy;
            d["status"] = p.status;
            d["cpu_s"] = p.cpuSeconds;
            d["steps"] = p.steps;
            d["realizations"] = p.realizations;
            d["peak_error"] = p.errors.peak;
            d["ripple_error"] = p.errors.ripple;
            d["speed_error"] = p.errors.speed;
            d["time_error"] = p.errors.time;
            d["energy"] = p.errors.energy;
            d["worst"] = p.errors.worst();
            d["front"] = p.onFront;
            return d;
        };
        py::dict d;
        d["reference"] = point(f.reference);
        py::list points;
        for (const auto& p : f.points) points.append(point(p));
        d["points"] = points;
        py::dict presets;
        for (const auto& p : f.presets)
            presets[py::str(p.name)] = p.point < 0 ? py::object(py::none()) : py::object(py::int_(p.point));
        d["presets"] = presets;
        d["targets"] = [&] {
            py::dict t;
            for (const auto& p : f.presets) t[py::str(p.name)] = p.target;
            return t;
        }();
        d["torque_floor"] = f.torqueFloor;
        d["steady_window"] = py::make_tuple(f.window.t0, f.window.t1);
        d["notes"] = f.notes;
        d["csv"] = frontCsv(f);
        if (writePresets) {
            const std::string file = presetsFileBeside(model);
            writeFileAtomically(file, frontPresetsYaml(f));
            d["presets_file"] = file;
        }
        return d;
    });

    py::class_<RunHandle>(m, "Run")
        .def_property_readonly("analysis", [](const RunHandle& r) { return r.run.result.analysis; })
        .def("table", [](const RunHandle& r) {
            const auto& x = r.run.result;
            return tableDict(x.tableName, x.columnNames, x.columnUnits, x.rows);
        })
        .def("extra_tables", [](const RunHandle& r) {
            py::list out;
            for (const auto& t : r.run.result.extraTables)
                out.append(tableDict(t.name, t.columnNames, t.columnUnits, t.rows));
            return out;
        })
        .def("results", [](const RunHandle& r) { return scalars(r.run.result.results); })
        .def("derived", [](const RunHandle& r) { return scalars(r.run.result.derived); })
        .def("notes", [](const RunHandle& r) { return r.run.result.notes; })
        // (verdict, text, kind, the CLI's exit code): kind and exit code
        // from driver/Api's one rule (verdictKind, runExitCode).
        .def("verdict", [](const RunHandle& r) {
            const auto& x = r.run.result;
            return py::make_tuple(x.verdict, x.verdictText, verdictKindName(verdictKind(x.verdict)), runExitCode(x));
        })
        .def("statistics", [](const RunHandle& r) {
            const auto& s = r.run.result.statistics;
            py::dict d;
            d["integrator"] = s.integrator;
            d["accuracy"] = s.accuracy;
            d["steps"] = s.steps;
            d["realizations"] = s.realizations;
            d["step_attempts"] = s.stepAttempts;
            d["consistency_restarts"] = s.consistencyRestarts;
            d["wall_seconds"] = r.run.info.wallSeconds;
            d["host"] = r.run.info.host;
            d["version"] = r.run.info.version;
            return d;
        })
        .def("linear_model", [](const RunHandle& r) {
            py::dict mats;
            for (const auto& mtx : r.run.result.matrices) {
                const std::size_t n = mtx.rows.empty() ? 0 : mtx.rows.front().size();
                py::array_t<double> a({static_cast<py::ssize_t>(mtx.rows.size()), static_cast<py::ssize_t>(n)});
                auto w = a.mutable_unchecked<2>();
                for (std::size_t i = 0; i < mtx.rows.size(); ++i)
                    for (std::size_t j = 0; j < n; ++j)
                        w(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j)) = j < mtx.rows[i].size() ? mtx.rows[i][j] : 0.0;
                mats[py::str(mtx.name)] = py::make_tuple(a, mtx.unit);
            }
            return py::make_tuple(r.run.result.dofNames, mats);
        })
        .def("summary_json", [](const RunHandle& r) { return formatSummaryJson(r.spec, r.run.result, r.run.info); })
        .def("write", [](const RunHandle& r, const std::string& dir) {
            std::string warning;
            std::vector<std::string> files;
            {
                py::gil_scoped_release release;
                files = writeRunFiles(dir, r.spec, r.run, warning);
            }
            return py::make_tuple(files, warning);
        });

    m.def("sweep", [](const std::string& model, const OverrideTriples& overrides,
                      const std::vector<std::string>& grids, const std::vector<std::string>& ranges, std::size_t lhs,
                      unsigned long seed, unsigned jobs, const std::string& outDir, py::object progress,
                      Token* token) {
        SweepSummary s;
        SweepOptions options;
        {
            py::gil_scoped_release release;
            options.model = model;
            options.baseOverrides = toOverrides(overrides);
            readModel(options.model, options.baseOverrides);  // one error, not one per point
            options.jobs = std::max(1u, jobs);
            options.outDir = outDir;
        }
        SweepPlan plan = makeSweepPlan(grids, ranges, lhs, seed);
        // Python's numbers are SI (docs/python.md): an axis given without a
        // unit is read so at every point, as `Model.set` reads a number.
        for (auto& axis : plan.axes) axis.bareNumberIsSI = axis.unit.empty();
        checkSweepPaths(plan.axes, options.baseOverrides);  // as the CLI: refused before anything runs
        // The sweep runs on a thread of its own while this one, holding the
        // GIL every 50 ms only, lets Python see Ctrl-C, calls `progress` and
        // watches the CancelToken: a signal, a token set or progress
        // returning False stops the running points at their next sample, no
        // further point starts, and the KeyboardInterrupt (or Cancelled) is
        // raised once the sweep has stopped (its finished points kept, as
        // the CLI's SIGINT leaves them).
        CancelFlag cancel;
        options.cancel = &cancel;
        std::atomic<std::size_t> done{0}, total{0}, failed{0};
        std::atomic<bool> reported{true};
        std::exception_ptr failure;
        std::atomic<bool> finished{false};
        std::thread worker([&] {
            try {
                s = runSweep(plan, options, [&](std::size_t d, std::size_t t, std::size_t f) {
                    done = d;
                    total = t;
                    failed = f;
                    reported = false;
                });
            } catch (...) {
                failure = std::current_exception();
            }
            finished = true;
        });
        bool interrupted = false;
        std::exception_ptr callbackError;
        auto report = [&] {
            if (progress.is_none() || reported.exchange(true) || callbackError || cancel.cancelled) return;
            try {
                const py::object answer = progress(done.load(), total.load(), failed.load());
                if (!answer.is_none() && PyObject_IsTrue(answer.ptr()) == 0) cancel.cancelled = true;
            } catch (py::error_already_set&) {
                callbackError = std::current_exception();  // raised once the sweep has stopped
                cancel.cancelled = true;
            }
        };
        while (!finished) {
            {
                py::gil_scoped_release release;
                for (int k = 0; k < 50 && !finished; ++k) std::this_thread::sleep_for(std::chrono::milliseconds(1));
            }
            if (!interrupted && PyErr_CheckSignals() != 0) {
                interrupted = true;  // the Python error (KeyboardInterrupt) stays set until we return
                cancel.cancelled = true;
            }
            if (token && token->flag->cancelled) cancel.cancelled = true;
            if (!interrupted) report();
        }
        {
            py::gil_scoped_release release;
            worker.join();
        }
        if (interrupted) throw py::error_already_set();
        if (callbackError) std::rethrow_exception(callbackError);
        if (!failure) report();  // the last point's progress
        if (failure) std::rethrow_exception(failure);
        py::dict d;
        d["run"] = s.run;
        d["resumed"] = s.resumed;
        d["failed"] = s.failed;
        d["errors"] = s.errors;
        d["total"] = s.total;
        d["files"] = s.files;
        return d;
    }, py::arg("model"), py::arg("overrides"), py::arg("grids"), py::arg("ranges"), py::arg("lhs"), py::arg("seed"),
       py::arg("jobs"), py::arg("out"), py::arg("progress") = py::none(), py::arg("token") = nullptr);

    m.def("validate", [](const std::string& filter) {
        std::vector<ValidationRow> rows;
        {
            py::gil_scoped_release release;
            rows = validate(filter);
        }
        py::list out;
        for (const auto& r : rows) {
            py::dict d;
            d["case"] = r.caseName;
            d["quantity"] = r.quantity;
            d["unit"] = r.unit;
            d["multibody"] = r.multibody ? py::object(py::float_(*r.multibody)) : py::object(py::none());
            d["oracle"] = r.oracle;
            d["paper"] = r.paper ? py::object(py::float_(*r.paper)) : py::object(py::none());
            // No relative error to an oracle of 0 (null in --json too): the absolute one.
            d["rel_error"] = r.oracle == 0 ? py::object(py::none()) : py::object(py::float_(r.relError));
            if (r.oracle == 0) d["abs_error"] = std::abs(judgedValue(r) - r.oracle);
            d["tolerance"] = r.tolerance;
            d["status"] = r.status;
            d["note"] = r.note;
            // An observation's expected band (None for other rows).
            d["band"] = r.band ? py::object(py::make_tuple(r.band->low, r.band->high)) : py::object(py::none());
            out.append(d);
        }
        return out;
    });

    m.def("elements", [] {
        py::list out;
        for (const ElementSchema* s : elementSchemas()) out.append(schemaDict(*s));
        return out;
    });
    m.def("analyses", [] {
        py::list out;
        for (const ElementSchema* s : analysisSchemas()) out.append(schemaDict(*s));
        return out;
    });
    // The reader's "did you mean" (ElementSchema.h): the candidate closest to
    // `word`, or "" if none is close enough to help.
    m.def("nearest_name", [](const std::string& word, const std::vector<std::string>& candidates) {
        return nearestName(word, candidates);
    });
    m.def("load_plugin", [](const std::string& path) { loadPlugin(path); });
    m.def("to_si", [](const std::string& text, const std::string& unit) {
        try {
            return units::toSI(text, unit);
        } catch (const std::invalid_argument& e) {
            // A unit that is not a coherent SI unit: the user's text here,
            // so the documented UnitError (issue 26 item 10), not ValueError.
            throw units::UnitError(e.what(), 0);
        }
    });
    m.def("parse_quantity", [](const std::string& text) {
        const units::Quantity q = units::parseQuantity(text);
        return py::make_tuple(q.value, q.dim.toString());
    });
}
