// Chapter 7 scene: the benchmark. Every method of bench::methods() on every scenario of
// bench::scenarios(), swept over steps or tolerances; each run timed (minimum over
// repetitions, integration only) and measured against the long-double Taylor reference.
// Writes work_precision.csv (every run), work_precision.md (the summary table), a
// work-precision diagram per scenario and the invariants of the 100-period Grioli runs.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bench.hpp"
#include "figure.hpp"
#include "scene.hpp"
#include "work_precision.gp.hpp"

namespace {

const double nan_ = std::numeric_limits<double>::quiet_NaN();

// The progress line on stderr: rewritten in place on a terminal, one line per scenario otherwise.
class Progress {
public:
    Progress() : tty_(isatty(2)), start_(std::chrono::steady_clock::now()) {}
    double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
    void scenario(int i, int n, const std::string& name) {
        index_ = i, count_ = n;
        if (!tty_) std::cerr << "work_precision: [" << i << "/" << n << "] " << name << " (" << seconds() << " s)\n";
    }
    void run(const std::string& what) {
        if (!tty_) return;
        std::cerr << "\r\033[K[" << index_ << "/" << count_ << "] " << what << "  (" << seconds() << " s)"
                  << std::flush;
    }
    void done() {
        if (tty_) std::cerr << "\r\033[K";
        std::cerr << "work_precision: done in " << seconds() << " s\n";
    }

private:
    std::string seconds() const {
        std::ostringstream s;
        s << std::fixed << std::setprecision(1) << elapsed();
        return s.str();
    }
    bool tty_;
    std::chrono::steady_clock::time_point start_;
    int index_ = 0, count_ = 0;
};

std::string sci(double x, int digits = 2) {
    if (!std::isfinite(x)) return "—";
    std::ostringstream s;
    s << std::setprecision(digits) << std::scientific << x;
    return s.str();
}

// A file written next to the figures, published with them when the scene succeeds.
void write_file(kit::Scene& scene, const std::string& name, const std::string& text) {
    if (!scene.options().figures()) return;
    const std::filesystem::path dir = scene.options().out_dir();
    std::filesystem::create_directories(dir);
    const std::string staged = (dir / ("." + name + ".partial")).string();
    std::ofstream(staged) << text;
    scene.stage_figure(staged, (dir / name).string());
}

// The diagrams, by family: one panel each for the adaptive explicit methods, the fixed-step
// methods and the implicit ones. A method finds its panel from its family and kind, and its
// colour and marker from its place in the panel, so a new method of bench::methods() slots in
// without a change here. Colours: Okabe and Ito's palette, safe for colour-blind readers. Each
// panel has its own set of markers, so that across the whole chapter (the invariants figure
// shows every method at once) no two methods share both colour and marker.
struct Panel {
    std::string title;
    std::vector<int> markers;  // gnuplot point types, one per method of the panel
    std::vector<const bench::Method*> methods;
};

std::vector<Panel> panels(const std::vector<bench::Method>& methods) {
    std::vector<Panel> p{{"adaptive, explicit (GSL; error-controlled by the tolerance)", {7, 5, 9, 11, 13, 15}, {}},
                         {"fixed step: your RK4, the geometric methods, the Taylor series", {6, 4, 8, 10, 12, 14}, {}},
                         {"implicit (GSL, with the analytic Jacobian)", {1, 2, 3}, {}}};
    for (const bench::Method& m : methods)
        p[m.family == "implicit" ? 2 : m.kind == bench::Kind::tolerance ? 0 : 1].methods.push_back(&m);
    return p;
}

// The line style of the i-th method of a panel.
std::string style(const Panel& panel, std::size_t i) {
    static const char* okabe_ito[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000"};
    const std::size_t n = sizeof okabe_ito / sizeof okabe_ito[0];
    return std::string("lc rgb '") + okabe_ito[i % n] + "' pt " +
           std::to_string(panel.markers[i % panel.markers.size()]);
}

// The scene's parameters, bound to its options.
struct Params {
    std::string sweep = "quick", scenario = "all";
    double target = 1e-10;
};

void declare(kit::Options& opts, Params& p) {
    std::vector<std::string> names{"all"};
    for (const bench::Scenario& s : bench::scenarios()) names.push_back(s.name);
    opts.choice("sweep", &p.sweep, {"smoke", "quick", "full"},
                "how much to run: quick (under a minute), full (finer sweeps, 5 repetitions, minutes), smoke (seconds)")
        .choice("scenario", &p.scenario, names, "run one scenario only")
        .real("target", &p.target, "the error at which the methods' run times are compared", kit::between(1e-15, 1e-2));
}

// Every run of the benchmark: per scenario its reference, per method its sweep.
struct Sweeps {
    bench::Budget b;
    double target;
    std::vector<bench::Scenario> all;
    std::map<std::string, bench::Reference> refs;
    std::map<std::string, std::map<std::string, std::vector<bench::Point>>> points;  // scenario -> method -> sweep
    double elapsed_s = 0;
};

Sweeps run_sweeps(const kit::Options& o, const Params& prm) {
    Sweeps w{bench::budget(prm.sweep), prm.target, {}, {}, {}, 0};
    const bench::Budget& b = w.b;
    for (const bench::Scenario& s : bench::scenarios())
        if (prm.scenario == "all" || prm.scenario == s.name) w.all.push_back(s);
    const auto& all = w.all;
    const auto& methods = bench::methods();
    // The work: per scenario, the long-double reference and each method's sweep, which stops
    // at the floor or at the budget's time per sweep (measured: about 0.15 of it on average).
    kit::require_budget(
        o, {double(all.size()), 0.3 + double(methods.size()) * (0.15 * b.max_sweep_s + 0.5 * b.max_run_s), "scenarios",
            "--sweep, --scenario"});
    auto& refs = w.refs;
    auto& points = w.points;
    Progress progress;
    for (std::size_t i = 0; i < all.size(); ++i) {
        const bench::Scenario& sc = all[i];
        progress.scenario(static_cast<int>(i + 1), static_cast<int>(all.size()), sc.name);
        progress.run(sc.name + "  long-double reference");
        refs[sc.name] = bench::reference(sc, b.self_check);
        for (const bench::Method& m : methods)
            points[sc.name][m.name] =
                bench::sweep(sc, m, refs[sc.name], b, [&](const std::string& what) { progress.run(what); });
    }
    progress.done();

    w.elapsed_s = progress.elapsed();
    return w;
}

// The CSV of every run (work_precision.csv), and the same as the report's table "runs".
void write_runs(kit::Scene& scene, const Sweeps& w) {
    const auto& all = w.all;
    const auto& methods = bench::methods();
    auto points = w.points;
    // The CSV: every run.
    std::ostringstream csv;
    csv << "scenario,method,kind,h_or_tol,run_time_s,repeats,evaluations,err_R_rad,err_Omega_rel,error,"
           "energy_drift,momentum_drift,orthogonality,status\n";
    csv << std::setprecision(6);
    std::vector<std::vector<double>> table;
    for (std::size_t si = 0; si < all.size(); ++si)
        for (std::size_t mi = 0; mi < methods.size(); ++mi)
            for (const bench::Point& p : points[all[si].name][methods[mi].name]) {
                csv << p.scenario << "," << p.method << ","
                    << (methods[mi].kind == bench::Kind::step ? "step" : "tolerance") << "," << p.param << ","
                    << p.time_s << "," << p.repeats << "," << p.evaluations << ",";
                if (p.failed) {
                    csv << ",,,,,,\"failed: " << p.why << "\"\n";
                    continue;
                }
                csv << p.m.err_R << "," << p.m.err_Omega << "," << p.m.error << "," << p.m.dH << "," << p.m.dL << ","
                    << p.m.orth << ",ok\n";
                table.push_back({double(si), double(mi), p.param, p.time_s, double(p.evaluations), p.m.err_R,
                                 p.m.err_Omega, p.m.dH, p.m.dL, p.m.orth});
            }
    write_file(scene, "work_precision.csv", csv.str());
    scene.report.table(
        "runs", {"scenario", "method", "h_or_tol", "time_s", "evaluations", "err_R", "err_Omega", "dH", "dL", "orth"},
        table, false);
}

// The summary (work_precision.md and the report): per scenario and method, the best error,
// and the time to reach the target.
// What the summary keeps while it writes: its markdown, the rows of by_method, and the best
// method on Grioli over 100 periods (the headline).
struct Summary {
    std::ostringstream md;
    std::vector<std::vector<double>> rows;
    const bench::Point* grioli_best = nullptr;
    std::string grioli_best_method;
};

// The fastest method to the target on one scenario, with and without the Taylor method.
struct Fastest {
    double time = std::numeric_limits<double>::infinity(), listed_time = time;
    std::string name = "none", listed_name = "none";
};

// The sweep of one method on one scenario (empty when it was not run).
const std::vector<bench::Point>& sweep_of(const Sweeps& w, const std::string& scenario, const std::string& method) {
    static const std::vector<bench::Point> none;
    const auto s = w.points.find(scenario);
    if (s == w.points.end()) return none;
    const auto m = s->second.find(method);
    return m == s->second.end() ? none : m->second;
}

// One scenario's table: a row per method (markdown and by_method), and its fastest methods.
Fastest summarize_methods(Summary& out, const Sweeps& w, std::size_t si, double t_rk8pd) {
    const bench::Scenario& sc = w.all[si];
    const auto& methods = bench::methods();
    Fastest f;
    for (std::size_t mi = 0; mi < methods.size(); ++mi) {
        const auto& pts = sweep_of(w, sc.name, methods[mi].name);
        const bench::Point* bp = bench::best(pts);
        const double t = bench::time_to_reach(pts, w.target);
        if (std::isfinite(t) && t < f.time) f.time = t, f.name = methods[mi].name;
        if (std::isfinite(t) && t < f.listed_time && methods[mi].name != "taylor16")
            f.listed_time = t, f.listed_name = methods[mi].name;
        if (!bp) {
            out.md << "| " << methods[mi].label << " | failed | | | | | | |\n";
            out.rows.push_back({100.0 * si + mi, double(si), double(mi), nan_, nan_, nan_, nan_, nan_, nan_, nan_});
            continue;
        }
        out.md << "| " << methods[mi].label << " | " << sci(bp->m.error) << " | " << sci(bp->time_s) << " | " << sci(t)
               << " | " << (std::isfinite(t) && std::isfinite(t_rk8pd) ? sci(t_rk8pd / t) : "—") << " | "
               << sci(bp->m.orth) << " | " << sci(bp->m.dH) << " | " << sci(bp->m.dL) << " |\n";
        out.rows.push_back({100.0 * si + mi, double(si), double(mi), bp->m.error, bp->time_s, t,
                            std::isfinite(t) ? t_rk8pd / t : nan_, bp->m.orth, bp->m.dH, bp->m.dL});
        if (sc.name == "grioli_100" && (!out.grioli_best || bp->m.error < out.grioli_best->m.error))
            out.grioli_best = bp, out.grioli_best_method = methods[mi].label;
    }
    return f;
}

// One scenario: its reference, its table, its fastest methods (markdown and report).
void summarize_scenario(kit::Scene& scene, Summary& out, const Sweeps& w, std::size_t si) {
    const bench::Scenario& sc = w.all[si];
    const bench::Reference& ref = w.refs.at(sc.name);
    const double target = w.target;
    const double t_rk8pd = bench::time_to_reach(sweep_of(w, sc.name, "rk8pd"), target);
    out.md << "\n## " << sc.title << "\n\nReference: h = " << sci(ref.h, 3) << ", " << sci(ref.time_s, 2)
           << " s; against itself at h/2: " << (ref.self_difference < 0 ? "not run" : sci(ref.self_difference))
           << "; against the closed form (" << (sc.exact ? sc.exact_name : "none")
           << "): " << (ref.exact_difference < 0 ? "—" : sci(ref.exact_difference))
           << "; double-precision floor (the same steps in double): " << sci(ref.double_floor)
           << " (expected eps kappa sqrt(steps) = " << sci(ref.expected_floor) << ", kappa = " << sci(ref.kappa)
           << ").\n\n"
           << "| method | best error | its run time (s) | time to " << sci(target, 0)
           << " (s) | rk8pd time / this | orthogonality | energy drift | momentum drift |\n"
           << "|---|---|---|---|---|---|---|---|\n";
    const Fastest f = summarize_methods(out, w, si, t_rk8pd);
    const std::string k = sc.name + "_";
    scene.report.add(k + "reference_self_difference", ref.self_difference, "long-double reference vs itself at h/2");
    scene.report.add(k + "reference_exact_difference", ref.exact_difference, "reference vs closed form (-1: none)");
    scene.report.add(k + "reference_time_s", ref.time_s);
    scene.report.add(k + "double_floor", ref.double_floor, "Taylor 24 in double vs the reference");
    scene.report.add(k + "kappa", ref.kappa, "growth of a change of the initial state");
    scene.report.add(k + "expected_floor", ref.expected_floor, "eps kappa sqrt(steps)");
    scene.report.add(k + "fastest_at_target", f.name);
    scene.report.add(k + "fastest_time_s", f.time);
    scene.report.add(k + "rk8pd_time_s", t_rk8pd);
    scene.report.add(k + "speedup_vs_rk8pd", t_rk8pd / f.time, "rk8pd run time / fastest run time at the target");
    scene.report.add(k + "fastest_without_taylor", f.listed_name, "the same, leaving out the Taylor method");
    scene.report.add(k + "fastest_without_taylor_time_s", f.listed_time);
    scene.report.add(k + "speedup_without_taylor", t_rk8pd / f.listed_time);
    out.md << "\nFastest to " << sci(target, 0) << ": " << f.name << " (" << sci(f.time) << " s, "
           << (std::isfinite(t_rk8pd / f.time) ? sci(t_rk8pd / f.time, 2) : "—") << " times faster than rk8pd); "
           << "without the Taylor method: " << f.listed_name << " (" << sci(f.listed_time) << " s).\n";
}

// The headline: the best method on Grioli over 100 periods, or the best of any when that
// scenario was not run.
void summary_headline(kit::Scene& scene, const Sweeps& w, const Summary& out) {
    if (out.grioli_best) {
        const double floor = w.refs.at("grioli_100").double_floor;
        scene.report.headline("best method on Grioli over 100 periods (" + out.grioli_best_method +
                                  "): angle between R and the long-double reference, and Omega relative",
                              out.grioli_best->m.error, out.grioli_best->time_s);
        scene.report.add("grioli_100_best_method", out.grioli_best_method);
        scene.report.add("grioli_100_best_error", out.grioli_best->m.error);
        scene.report.add("grioli_100_best_over_floor", out.grioli_best->m.error / floor, "target: <= 10");
        // rk8pd's floor with GSL's driver and with the time kept as a two-part sum.
        const bench::Point* plain = bench::best(sweep_of(w, "grioli_100", "rk8pd"));
        const bench::Point* compensated = bench::best(sweep_of(w, "grioli_100", "rk8pd_ct"));
        if (plain && compensated) {
            scene.report.add("rk8pd_floor_gain", plain->m.error / compensated->m.error,
                             "Grioli, 100 periods: rk8pd's best error, GSL's driver over compensated time");
            scene.report.add("rk8pd_ct_over_floor", compensated->m.error / floor,
                             "compensated rk8pd's best / the floor");
        }
        return;
    }
    const bench::Point* any = nullptr;
    for (const auto& [s, per] : w.points)
        for (const auto& [m, pts] : per)
            if (const bench::Point* p = bench::best(pts); p && (!any || p->m.error < any->m.error)) any = p;
    if (!any) throw kit::NumericalFailure("no method produced a finite solution");
    scene.report.headline("best error of any method on " + any->scenario, any->m.error, any->time_s);
}

// The summary: per scenario and method, the best error, and the time to reach the target.
void write_summary(kit::Scene& scene, const Sweeps& w) {
    const auto& methods = bench::methods();
    Summary out;
    out.md << "# Work-precision summary (sweep: " << w.b.name << ")\n\n"
           << "Error: the larger of the angle between R and the reference (rad) and |Omega - Omega_ref| / max|Omega|, "
              "largest over the output times. Run time: integration only, minimum over "
           << w.b.repeats << " repetitions. Time to " << sci(w.target, 0)
           << ": interpolated on the lower envelope of the sweep. Reference: Taylor degree 24 in long double.\n";
    for (std::size_t si = 0; si < w.all.size(); ++si) summarize_scenario(scene, out, w, si);
    scene.report.table("by_method",
                       {"key", "scenario", "method", "best_error", "best_time_s", "time_to_target_s",
                        "speedup_vs_rk8pd", "orthogonality", "energy_drift", "momentum_drift"},
                       out.rows, false);
    out.md << "\nMethods: ";
    for (std::size_t mi = 0; mi < methods.size(); ++mi) out.md << (mi ? ", " : "") << mi << " = " << methods[mi].name;
    out.md << ". Scenarios: ";
    for (std::size_t si = 0; si < w.all.size(); ++si) out.md << (si ? ", " : "") << si << " = " << w.all[si].name;
    out.md << ".\n";
    write_file(scene, "work_precision.md", out.md.str());
    summary_headline(scene, w, out);
}

// "Order is slope": for each fixed-step method on each scenario, the least-squares slope of
// log10(error) against log10(run time) and against log10(evaluations of the equations, a fixed
// number per step), over the runs whose error lies
// between 1e3 times the scenario's double-precision floor and 1e-3 (clear of the floor and of the
// first, coarsest steps). A method of order p has slope -p against steps (or evaluations); against run time the
// same, as far as the time is proportional to the steps. Fewer than three runs there: NaN.
void report_slopes(kit::Scene& scene, const Sweeps& w) {
    auto fit = [](const std::vector<double>& x, const std::vector<double>& y) {
        double mx = 0, my = 0;
        for (std::size_t i = 0; i < x.size(); ++i) mx += x[i] / double(x.size()), my += y[i] / double(x.size());
        double sxy = 0, sxx = 0;
        for (std::size_t i = 0; i < x.size(); ++i) sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
        return sxy / sxx;
    };
    for (const bench::Scenario& sc : w.all) {
        const double floor = w.refs.at(sc.name).double_floor;
        for (const bench::Method& m : bench::methods()) {
            if (m.kind != bench::Kind::step || !w.points.at(sc.name).count(m.name)) continue;
            std::vector<double> lt, ls, le;
            for (const bench::Point& pt : w.points.at(sc.name).at(m.name))
                if (!pt.failed && pt.m.error < 1e-3 && pt.m.error > 1e3 * floor && pt.time_s > 0 && pt.evaluations > 0)
                    lt.push_back(std::log10(pt.time_s)), ls.push_back(std::log10(double(pt.evaluations))),
                        le.push_back(std::log10(pt.m.error));
            // Too few runs in that band (a light sweep): the keys are still there, not measured.
            const bool few = lt.size() < 3;
            const std::string k = sc.name + "_" + m.name + "_slope_";
            scene.report.add(k + "points", double(lt.size()),
                             "the runs in that band: under 3 and the two slopes are not measured (null)");
            scene.report.add(k + "time", few ? nan_ : fit(lt, le),
                             "d log10(error) / d log10(run time), errors in (1e3 floor, 1e-3)");
            scene.report.add(k + "evaluations", few ? nan_ : fit(ls, le),
                             "d log10(error) / d log10(evaluations of the equations, proportional to the steps), "
                             "the same runs");
        }
    }
}

// The right-hand side itself, on the first scenario run (Grioli's heavy top when it is there).
void report_rhs_cost(kit::Scene& scene, const Sweeps& w) {
    const auto& all = w.all;
    const bench::Scenario& rs = all.size() > 1 ? all[1] : all.front();
    const bench::RhsCost cost = bench::rhs_cost(rs.top, rs.s0);
    scene.report.add("rhs_scenario", rs.name, "the top whose right-hand side is timed");
    scene.report.add("rhs_teaching_ns", cost.teaching_ns, "euler_poisson_rhs through OdeRhs, as GSL calls it (ns)");
    scene.report.add("rhs_fast_ns", cost.fast_ns, "EulerPoissonInPlace through OdeRhsInPlace, as GSL calls it (ns)");
    scene.report.add("rhs_plain_ns", cost.plain_ns, "a hand-written loop on std::array, called directly (ns)");
    scene.report.add("rhs_fast_over_plain", cost.fast_ns / cost.plain_ns, "target: <= 1.5");
    scene.report.add("rhs_teaching_over_plain", cost.teaching_ns / cost.plain_ns);
    scene.report.add("rhs_fast_vs_teaching", cost.fast_vs_teaching,
                     "largest difference / max |dy/dt|, 1000 random states");
    scene.report.add("rhs_fast_vs_plain", cost.fast_vs_plain, "the same against the hand-written loop");
    if (!(cost.fast_vs_teaching <= 1e-13 && cost.fast_vs_plain <= 1e-13))
        throw kit::CheckFailed("the fast right-hand side and euler_poisson_rhs (or the plain loop) disagree by " +
                               std::to_string(std::max(cost.fast_vs_teaching, cost.fast_vs_plain)) +
                               " of |dy/dt|: the GSL methods of this benchmark would not integrate your equations");
    scene.report.add("sweep", w.b.name);
    scene.report.add("repeats", static_cast<long>(w.b.repeats));
    scene.report.add("wall_time_s", w.elapsed_s);
}

// One panel of a work-precision diagram: its family's methods (a method with no run that finished
// keeps its line in the key), and rk8pd in grey where it is not one of them.
void draw_panel(kit::Figure& fig, const Panel& panel, std::map<std::string, std::vector<bench::Point>>& by_method,
                double floor, double target) {
    std::vector<kit::Fill> plot, comparison;
    std::vector<std::vector<std::vector<double>>> blocks;
    auto curve = [&](const bench::Method& m) {
        std::vector<std::vector<double>> rows;
        for (const bench::Point& p : by_method[m.name])
            if (!p.failed) rows.push_back({p.time_s, std::max(p.m.error, 1e-16)});
        return rows;
    };
    bool has_rk8pd = false;
    for (std::size_t i = 0; i < panel.methods.size(); ++i) {
        const bench::Method& m = *panel.methods[i];
        has_rk8pd = has_rk8pd || m.name == "rk8pd";
        auto rows = curve(m);
        // A method with no run that finished still has its line in the key.
        plot.push_back({{"style", style(panel, i)},
                        {"title", kit::quoted(m.label + (rows.empty() ? " (every run failed)" : ""))}});
        if (rows.empty()) rows.push_back({1e300, 1e300});
        blocks.push_back(rows);
    }
    if (!has_rk8pd) {
        auto rows = curve(bench::method("rk8pd"));
        if (rows.empty()) rows.push_back({1e300, 1e300});
        comparison.push_back({});
        blocks.push_back(rows);
    }
    fig.script(kit::gp::plot, {{"curves", kit::joined(kit::gp::method, plot)},
                               {"comparison", kit::joined(kit::gp::rk8pd, comparison, "")},
                               {"floor", sci(floor, 6)},
                               {"target", sci(target, 6)},
                               {"target_text", sci(target, 0)}});
    for (const auto& rows : blocks) fig.data(rows);
}

void draw_work_precision(kit::Scene& scene, const Sweeps& w) {
    const double target = w.target;
    const auto& all = w.all;
    const auto& methods = bench::methods();
    auto refs = w.refs;
    auto points = w.points;
    // The diagrams: one per scenario, a panel per family of methods (panels() above), all
    // three on the same axes; rk8pd, the general-purpose favourite, is drawn grey in the
    // panels it does not belong to, for comparison. Keys stand to the right of their panel.
    const std::vector<Panel> by_family = panels(methods);
    const int n_panels = static_cast<int>(by_family.size());
    for (const bench::Scenario& sc : all) {
        const int height_px = 280 * n_panels + 90;
        kit::Figure fig(scene, "wp_" + sc.name + ".svg", 900, height_px);
        if (!fig.enabled()) continue;
        double t_min = 1e300, t_max = 0;
        for (const bench::Method& m : methods)
            for (const bench::Point& p : points[sc.name][m.name])
                if (!p.failed) t_min = std::min(t_min, p.time_s), t_max = std::max(t_max, p.time_s);
        if (t_max <= 0) continue;
        const double top = 1 - 50.0 / height_px, height = top - 55.0 / height_px;
        fig.script(kit::gp::work_precision, {{"title", kit::quoted(sc.title + ": error against run time")},
                                             {"tmin", sci(t_min / 1.5, 3)},
                                             {"tmax", sci(t_max * 1.5, 3)}});
        const double floor = refs[sc.name].double_floor;
        for (int k = 0; k < n_panels; ++k) {
            const Panel& panel = by_family[k];
            const double y1 = top - height * k / n_panels, y0 = top - height * (k + 1) / n_panels;
            // The panels share the time axis: its numbers only under the last one.
            fig.script(k + 1 == n_panels ? kit::gp::bottom_panel : kit::gp::panel,
                       {{"top", std::to_string(y1 - 30.0 / height_px)},
                        {"bottom", std::to_string(y0 + 8.0 / height_px)},
                        {"title", kit::quoted(panel.title)}});
            draw_panel(fig, panel, points[sc.name], floor, target);
        }
        fig.finish();
    }
}

void draw_invariants(kit::Scene& scene, const Sweeps& w) {
    auto points = w.points;
    const std::vector<Panel> by_family = panels(bench::methods());
    if (points.count("grioli_100")) {
        // Every method in each panel, in the colour and marker of its work-precision panel; one
        // key for the three panels, on their right.
        kit::Figure fig(scene, "invariants_grioli_100.svg", 1400, 560);
        if (fig.enabled()) {
            fig.script(kit::gp::invariants);
            for (int panel = 0; panel < 3; ++panel) {
                const char* titles[3][2] = {{"energy: |H − H(0)| / (T(0) + f)", "energy drift"},
                                            {"vertical angular momentum ({/:Bold k}, RJΩ)", "drift / |JΩ(0)|"},
                                            {"orthogonality: ‖R^T R − 1‖_F", "orthogonality defect"}};
                std::vector<kit::Fill> plot;
                std::vector<std::vector<std::vector<double>>> blocks;
                for (const Panel& family : by_family)
                    for (std::size_t i = 0; i < family.methods.size(); ++i) {
                        const bench::Method& m = *family.methods[i];
                        std::vector<std::vector<double>> rows;
                        for (const bench::Point& p : points["grioli_100"][m.name])
                            if (!p.failed)
                                rows.push_back({p.time_s, std::max(panel == 0   ? p.m.dH
                                                                   : panel == 1 ? p.m.dL
                                                                                : p.m.orth,
                                                                   1e-17)});
                        if (rows.empty()) continue;
                        plot.push_back({{"style", style(family, i)}, {"title", kit::quoted(m.name)}});
                        blocks.push_back(rows);
                    }
                fig.script(panel == 2 ? kit::gp::invariants_key_panel : kit::gp::invariants_panel,
                           {{"title", kit::quoted(titles[panel][0])},
                            {"ylabel", kit::quoted(titles[panel][1])},
                            {"curves", kit::joined(kit::gp::invariant, plot)}});
                for (const auto& rows : blocks) fig.data(rows);
            }
            fig.finish();
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("work_precision", "Chapter 7: error against run time for every method and scenario");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&p](const kit::Options& o, kit::Scene& scene) {
        const Sweeps w = run_sweeps(o, p);
        write_runs(scene, w);
        write_summary(scene, w);
        report_slopes(scene, w);
        report_rhs_cost(scene, w);
        draw_work_precision(scene, w);
        draw_invariants(scene, w);
    });
}
