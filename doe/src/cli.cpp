#include "paddy/doe/cli.hpp"

#include "paddy/doe/box_behnken.hpp"
#include "paddy/doe/central_composite.hpp"
#include "paddy/doe/discovery_json.hpp"
#include "paddy/doe/error.hpp"
#include "paddy/doe/factorial.hpp"
#include "paddy/doe/plackett_burman.hpp"
#include "paddy/doe/plots.hpp"
#include "paddy/doe/report_text.hpp"

#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>
#include <map>

namespace paddy::doe {

namespace {

double parseNumber(const std::string& s, const std::string& what) {
  std::size_t pos = 0;
  double v = 0;
  try {
    v = std::stod(s, &pos);
  } catch (...) {
    pos = 0;
  }
  if (pos != s.size() || s.empty()) throw DoeError(what + ": '" + s + "' is not a number");
  return v;
}

// "name=a:b" -> {name, {a, b}}
std::map<std::string, std::pair<double, double>> parseRanges(const std::vector<std::string>& specs, const std::string& opt) {
  std::map<std::string, std::pair<double, double>> out;
  for (const auto& s : specs) {
    const auto eq = s.find('='), colon = s.rfind(':');
    if (eq == std::string::npos || colon == std::string::npos || colon < eq || eq == 0)
      throw DoeError(opt + " '" + s + "': expected NAME=LOW:HIGH");
    const double lo = parseNumber(s.substr(eq + 1, colon - eq - 1), opt + " " + s);
    const double hi = parseNumber(s.substr(colon + 1), opt + " " + s);
    if (!(hi > lo)) throw DoeError(opt + " '" + s + "': HIGH must be greater than LOW");
    out[s.substr(0, eq)] = {lo, hi};
  }
  return out;
}

std::map<std::string, double> parseValues(const std::vector<std::string>& specs, const std::string& opt) {
  std::map<std::string, double> out;
  for (const auto& s : specs) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0) throw DoeError(opt + " '" + s + "': expected NAME=VALUE");
    out[s.substr(0, eq)] = parseNumber(s.substr(eq + 1), opt + " " + s);
  }
  return out;
}

nlohmann::json readJson(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw DoeError("cannot open '" + path + "' for reading");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw DoeError(path + ": not valid JSON (" + e.what() + ")");
  }
}

int factorIndex(const std::vector<Factor>& f, const std::string& name) {
  std::string avail;
  for (std::size_t j = 0; j < f.size(); ++j) {
    if (f[j].name == name) return static_cast<int>(j);
    avail += (avail.empty() ? "" : ", ") + f[j].name;
  }
  throw DoeError("unknown factor '" + name + "' (factors: " + avail + ")");
}

struct DesignArgs {
  std::string type, csv, json, alpha = "rotatable", ccdType = "circumscribed";
  int factors = 0, center = 0, replicates = 1, runs = 0;
  std::vector<std::string> names, levels, generators;
  long long seed = -1;
};

int doDesign(const DesignArgs& a, std::ostream& out) {
  int k = a.names.empty() ? a.factors : static_cast<int>(a.names.size());
  if (!a.names.empty() && a.factors && a.factors != k)
    throw DoeError("--factors " + std::to_string(a.factors) + " disagrees with " + std::to_string(k) + " --names");
  if (k < 1) throw DoeError("give the number of factors (--factors N) or their names (--names A,B,C)");
  Design d;
  if (a.type == "pb") d = plackettBurman(a.runs ? a.runs : plackettBurmanRunsFor(k), k);
  else if (a.type == "bbd") d = boxBehnken(k, 0);
  else if (a.type == "factorial") d = a.generators.empty() ? fullFactorial(k) : fractionalFactorial(k, a.generators);
  else if (a.type == "ccd") {
    CcdOptions o;
    if (a.ccdType == "circumscribed") o.type = CcdType::Circumscribed;
    else if (a.ccdType == "inscribed") o.type = CcdType::Inscribed;
    else if (a.ccdType == "face") o.type = CcdType::FaceCentred;
    else throw DoeError("--ccd-type must be circumscribed, inscribed or face");
    if (a.alpha == "face") o.type = CcdType::FaceCentred;
    else if (a.alpha != "rotatable") o.alpha = parseNumber(a.alpha, "--alpha");
    o.generators = a.generators;
    d = centralComposite(k, o);
  } else throw DoeError("unknown design '" + a.type + "' (pb, bbd, ccd, factorial)");
  addCenterPoints(d, a.center);
  std::vector<Factor> f = defaultFactors(k);
  for (int j = 0; j < k && !a.names.empty(); ++j) f[j].name = a.names[j];
  for (const auto& [name, lv] : parseRanges(a.levels, "--levels")) {
    const int j = factorIndex(f, name);
    f[j].low = lv.first;
    f[j].high = lv.second;
  }
  setFactors(d, f);
  d = replicate(d, a.replicates);
  if (a.seed >= 0) randomize(d, static_cast<std::uint64_t>(a.seed));
  std::vector<std::string> header{"run", "std", "type"};
  for (const auto& x : f) header.push_back(x.name);
  for (const auto& x : f) header.push_back(x.name + "_coded");
  std::vector<std::vector<std::string>> rows;
  const Eigen::MatrixXd real = d.real();
  for (int i = 0; i < d.runs(); ++i) {
    std::vector<std::string> r{std::to_string(i + 1), std::to_string(d.stdOrder[i]), pointTypeName(d.type[i])};
    for (int j = 0; j < k; ++j) r.push_back(formatNumber(real(i, j)));
    for (int j = 0; j < k; ++j) r.push_back(formatNumber(d.coded(i, j)));
    rows.push_back(r);
  }
  writeFileAtomic(a.csv, toCsv(header, rows));
  if (!a.json.empty()) writeFileAtomic(a.json, designToJson(d).dump(2) + "\n");
  printDesign(out, d);
  out << "wrote " << a.csv << " (" << d.runs() << " runs)\n";
  return 0;
}

struct AnalyzeArgs {
  std::string data, model = "linear", json, plots;
  std::vector<std::string> factors, responses, levels;
};

int doAnalyze(const AnalyzeArgs& a, std::ostream& out) {
  AnalysisRequest req;
  req.factors = a.factors;
  req.responses = a.responses;
  req.model = a.model;
  req.levels = parseRanges(a.levels, "--levels");
  const Analysis an = analyzeTable(readCsv(a.data), req);
  printAnalysis(out, an);
  if (!a.json.empty()) {
    writeFileAtomic(a.json, analysisToJson(an).dump(2) + "\n");
    out << "\nwrote " << a.json << "\n";
  }
  if (!a.plots.empty()) {
    const auto files = plotAnalysis(a.plots, an);
    out << "wrote " << files.size() << " plot files to " << a.plots << "\n";
  }
  return 0;
}

struct OptimizeArgs {
  std::string fit, json, plots;
  std::vector<std::string> goals, bounds;
  int starts = 40, solutions = 10;
  long long seed = 12345;
};

int doOptimize(const OptimizeArgs& a, std::ostream& out) {
  const FitModels fit = fitFromJson(readJson(a.fit));
  std::vector<GoalSpec> goals;
  for (const auto& g : a.goals) {
    const auto eq = g.find('=');
    const auto& r = fit.response(eq == std::string::npos ? g : g.substr(0, eq));
    goals.push_back(parseGoal(g, r.yMin, r.yMax));
  }
  const int k = static_cast<int>(fit.factors.size());
  OptimizeOptions o;
  o.starts = a.starts;
  o.seed = static_cast<std::uint64_t>(a.seed);
  o.maxSolutions = a.solutions;
  o.lowerCoded.resize(k);
  o.upperCoded.resize(k);
  for (int j = 0; j < k; ++j) {
    o.lowerCoded(j) = fit.factors[j].toCoded(fit.dataMin[j]);
    o.upperCoded(j) = fit.factors[j].toCoded(fit.dataMax[j]);
  }
  for (const auto& [name, lv] : parseRanges(a.bounds, "--bounds")) {
    const int j = factorIndex(fit.factors, name);
    o.lowerCoded(j) = fit.factors[j].toCoded(lv.first);
    o.upperCoded(j) = fit.factors[j].toCoded(lv.second);
  }
  const auto sols = optimizeDesirability(fit.factors, fit.responses, goals, o);
  printSolutions(out, fit, goals, sols);
  if (!a.json.empty()) {
    writeFileAtomic(a.json, solutionsToJson(fit, goals, sols).dump(2) + "\n");
    out << "wrote " << a.json << "\n";
  }
  if (!a.plots.empty()) plotDesirabilityRamps(a.plots, goals);
  return 0;
}

struct PathArgs {
  std::string fit, response, key, csv;
  bool descent = false, real = false;
  double step = 1.0;
  int steps = 5;
  std::vector<std::string> realSteps, origin;
};

int doPath(const PathArgs& a, std::ostream& out) {
  const FitModels fit = fitFromJson(readJson(a.fit));
  const auto& r = fit.response(a.response);
  const auto steps = parseValues(a.realSteps, "--real-steps");
  std::vector<int> idx;  // factors on the path
  for (std::size_t j = 0; j < fit.factors.size(); ++j)
    if (steps.empty() || steps.count(fit.factors[j].name)) idx.push_back(static_cast<int>(j));
  for (const auto& [name, v] : steps) factorIndex(fit.factors, name);
  std::vector<Factor> f;
  Eigen::VectorXd b(idx.size());
  for (std::size_t i = 0; i < idx.size(); ++i) {
    f.push_back(fit.factors[idx[i]]);
    Term t{std::vector<int>(fit.factors.size(), 0)};
    t.powers[idx[i]] = 1;
    const auto it = std::find(r.model.terms.begin(), r.model.terms.end(), t);
    if (it == r.model.terms.end()) throw DoeError("the model of " + r.name + " has no main effect " + f.back().name);
    b(static_cast<Eigen::Index>(i)) = r.beta(it - r.model.terms.begin());
  }
  PathOptions o;
  o.ascent = !a.descent;
  o.steps = a.steps;
  for (const auto& x : f)
    if (!steps.empty()) o.realSteps.push_back(steps.at(x.name));
  if (!a.key.empty()) {
    const int j = factorIndex(f, a.key);
    o.keyFactor = j;
  }
  o.keyStep = a.step;
  o.keyStepReal = a.real;
  if (!a.origin.empty()) {
    Eigen::VectorXd org(f.size());
    for (std::size_t j = 0; j < f.size(); ++j) org(static_cast<Eigen::Index>(j)) = f[j].center();
    for (const auto& [name, v] : parseValues(a.origin, "--origin")) org(factorIndex(f, name)) = v;
    o.originReal = org;
  }
  const auto path = steepestPath(f, b, o);
  std::vector<std::string> header{"step"};
  for (const auto& x : f) header.push_back(x.name);
  header.push_back(r.name + "_predicted");
  std::vector<std::vector<std::string>> rows;
  for (const auto& p : path) {
    Eigen::VectorXd full = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(fit.factors.size()));
    for (std::size_t i = 0; i < idx.size(); ++i) full(idx[i]) = p.coded(static_cast<Eigen::Index>(i));
    std::vector<std::string> row{std::to_string(p.step)};
    for (Eigen::Index j = 0; j < p.real.size(); ++j) row.push_back(formatNumber(p.real(j)));
    row.push_back(formatNumber(r.predict(full)));
    rows.push_back(row);
  }
  const std::string text = toCsv(header, rows);
  out << text;
  if (!a.csv.empty()) writeFileAtomic(a.csv, text);
  return 0;
}

struct DiagnoseArgs {
  std::string input, json;
};

int doDiagnose(const DiagnoseArgs& a, std::ostream& out) {
  const Diagnosis d = diagnose(diagnoseInputFromJson(readJson(a.input)));
  printDiagnosis(out, d);
  if (!a.json.empty()) {
    writeFileAtomic(a.json, diagnosisToJson(d).dump(2) + "\n");
    out << "wrote " << a.json << "\n";
  }
  return 0;
}

}  // namespace

int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"Designed experiments and response-surface statistics", "paddy doe"};
  app.require_subcommand(1);
  DesignArgs da;
  auto* design = app.add_subcommand("design", "generate a design and write it as CSV");
  design->add_option("type", da.type, "pb, bbd, ccd or factorial")->required();
  design->add_option("--factors", da.factors, "number of factors");
  design->add_option("--names", da.names, "factor names")->delimiter(',');
  design->add_option("--levels", da.levels, "real levels NAME=LOW:HIGH (coded -1/+1)");
  design->add_option("--center", da.center, "centre points");
  design->add_option("--replicates", da.replicates, "replicates of the whole design");
  design->add_option("--seed", da.seed, "randomise the run order with this seed");
  design->add_option("--alpha", da.alpha, "CCD axial distance: rotatable, face or a number");
  design->add_option("--ccd-type", da.ccdType, "circumscribed, inscribed or face");
  design->add_option("--runs", da.runs, "Plackett-Burman run count (8, 12, 16, 20, 24)");
  design->add_option("--generators", da.generators, "fractional generators, e.g. D=ABC");
  design->add_option("--csv", da.csv, "output CSV")->required();
  design->add_option("--json", da.json, "optional JSON output");

  AnalyzeArgs aa;
  auto* analyze = app.add_subcommand("analyze", "fit a model to each response and print the ANOVA");
  analyze->add_option("data", aa.data, "CSV with one row per run")->required();
  analyze->add_option("--factors", aa.factors, "factor columns")->delimiter(',')->required();
  analyze->add_option("--responses", aa.responses, "response columns")->delimiter(',')->required();
  analyze->add_option("--model", aa.model, "linear, linear+curvature, 2fi, quadratic or a term list");
  analyze->add_option("--levels", aa.levels, "explicit coding NAME=LOW:HIGH (default: column min/max)");
  analyze->add_option("--json", aa.json, "write the analysis as JSON");
  analyze->add_option("--plots", aa.plots, "write plots (PNG + SVG) into this directory");

  OptimizeArgs oa;
  auto* optimize = app.add_subcommand("optimize", "desirability optimisation of a fitted JSON");
  optimize->add_option("fit", oa.fit, "JSON written by analyze")->required();
  optimize->add_option("--goal", oa.goals, "NAME=target:V | max | min | range [,lo=,hi=,w=,w2=,imp=]")->required();
  optimize->add_option("--bounds", oa.bounds, "search range NAME=LOW:HIGH (default: data range)");
  optimize->add_option("--starts", oa.starts, "number of random starts");
  optimize->add_option("--seed", oa.seed, "seed of the starts");
  optimize->add_option("--solutions", oa.solutions, "solutions to report");
  optimize->add_option("--json", oa.json, "write solutions as JSON");
  optimize->add_option("--plots", oa.plots, "write desirability ramps into this directory");

  PathArgs pa;
  auto* path = app.add_subcommand("path", "path of steepest ascent/descent from a first-order fit");
  path->add_option("fit", pa.fit, "JSON written by analyze")->required();
  path->add_option("--response", pa.response, "response name")->required();
  path->add_flag("--descent", pa.descent, "steepest descent instead of ascent");
  path->add_option("--key", pa.key, "key factor (default: largest |coefficient|)");
  path->add_option("--step", pa.step, "key factor step (coded units unless --real)");
  path->add_flag("--real", pa.real, "--step is in real units");
  path->add_option("--real-steps", pa.realSteps, "fixed real steps NAME=STEP (only these factors move)");
  path->add_option("--origin", pa.origin, "start NAME=VALUE in real units (default: centre)");
  path->add_option("--steps", pa.steps, "number of steps");
  path->add_option("--csv", pa.csv, "write the path as CSV");

  DiagnoseArgs ga;
  auto* diag = app.add_subcommand("diagnose", "score tests of candidate missing effects (docs/doe.md)");
  diag->add_option("input", ga.input, "JSON with residual, covariance or sigma, jacobian, candidates")->required();
  diag->add_option("--json", ga.json, "write the diagnosis as JSON");

  std::vector<char*> argv;
  std::vector<std::string> copy = args;
  for (auto& s : copy) argv.push_back(s.data());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e, out, err);
    return rc == 0 ? 0 : 2;
  }
  try {
    if (*design) return doDesign(da, out);
    if (*analyze) return doAnalyze(aa, out);
    if (*optimize) return doOptimize(oa, out);
    if (*path) return doPath(pa, out);
    if (*diag) return doDiagnose(ga, out);
  } catch (const std::exception& e) {
    err << "paddy doe: error: " << e.what() << "\n";
    return 2;
  }
  return 2;
}

int runCli(int argc, char** argv) {
  std::vector<std::string> args(argv, argv + argc);
  if (args.empty()) args.push_back("doe");
  return runCli(args, std::cout, std::cerr);
}

}  // namespace paddy::doe
