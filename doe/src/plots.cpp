#include "paddy/doe/plots.hpp"

#include "paddy/doe/csv.hpp"
#include "paddy/doe/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

namespace paddy::doe {

namespace fs = std::filesystem;

namespace {

std::string safe(const std::string& s) {
  std::string o;
  for (char c : s) o += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
  return o;
}

std::string quoteShell(const std::string& s) {
  std::string o = "'";
  for (char c : s) o += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return o + "'";
}

std::string gpString(const std::string& s) {  // single-quoted gnuplot string
  std::string o;
  for (char c : s) o += c == '\'' ? std::string("''") : std::string(1, c);
  return "'" + o + "'";
}

// Writes base.gp rendering `body` to base.png and base.svg, runs gnuplot in dir.
std::vector<std::string> render(const std::string& dir, const std::string& base, const std::string& body) {
  std::string gp;
  gp += "set terminal pngcairo size 900,650 noenhanced font 'Sans,10'\nset output '" + base + ".png'\n" + body;
  gp += "\nunset output\nset terminal svg size 900,650 noenhanced\nset output '" + base + ".svg'\n" + body + "\nunset output\n";
  writeFileAtomic((fs::path(dir) / (base + ".gp")).string(), gp);
  const std::string cmd = "cd " + quoteShell(dir) + " && gnuplot " + quoteShell(base + ".gp") + " > " +
                          quoteShell(base + ".log") + " 2>&1";
  if (std::system(cmd.c_str()) != 0) {
    std::ifstream log(fs::path(dir) / (base + ".log"));
    std::stringstream ss;
    ss << log.rdbuf();
    throw DoeError("gnuplot failed on " + (fs::path(dir) / (base + ".gp")).string() + ": " + ss.str());
  }
  fs::remove(fs::path(dir) / (base + ".log"));
  return {(fs::path(dir) / (base + ".png")).string(), (fs::path(dir) / (base + ".svg")).string()};
}

void prepare(const std::string& dir) {
  if (!gnuplotAvailable())
    throw DoeError("plots need gnuplot, which was not found on PATH (install gnuplot-nox)");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw DoeError("cannot create plot directory '" + dir + "': " + ec.message());
}

void writeData(const std::string& dir, const std::string& name, const std::string& text) {
  writeFileAtomic((fs::path(dir) / name).string(), text);
}

void append(std::vector<std::string>& a, const std::vector<std::string>& b) { a.insert(a.end(), b.begin(), b.end()); }

}  // namespace

bool gnuplotAvailable() { return std::system("command -v gnuplot > /dev/null 2>&1") == 0; }

std::vector<std::string> plotAnalysis(const std::string& dir, const Analysis& a) {
  prepare(dir);
  std::vector<std::string> files;
  for (const auto& r : a.responses) {
    const std::string rs = safe(r.response);
    // Pareto chart of |t|
    std::vector<const CoefficientRow*> rows;
    for (const auto& c : r.coefficients)
      if (c.term != "Intercept" && std::isfinite(c.t)) rows.push_back(&c);
    std::sort(rows.begin(), rows.end(), [](auto* x, auto* y) { return std::abs(x->t) > std::abs(y->t); });
    std::string dat = "# index |t| sign term\n";
    for (std::size_t i = 0; i < rows.size(); ++i)
      dat += fmt::format("{} {:.10g} {} \"{}\"\n", i, std::abs(rows[i]->t), rows[i]->t >= 0 ? 1 : 2, rows[i]->term);
    writeData(dir, "pareto_" + rs + ".dat", dat);
    append(files, render(dir, "pareto_" + rs,
                         fmt::format("set title {}\nset ylabel '|t-value|'\nset style fill solid 0.8\nset boxwidth 0.6\n"
                                     "set xtics rotate by -45\nset yrange [0:*]\nset key top right\n"
                                     "plot 'pareto_{}.dat' using 1:($3 == 1 ? $2 : 1/0):xtic(4) with boxes "
                                     "lc rgb '#d95f02' title 'positive effect', "
                                     "'' using 1:($3 == 2 ? $2 : 1/0) with boxes lc rgb '#1b9e77' title 'negative effect', "
                                     "{:.10g} with lines dt 2 lw 2 lc rgb 'black' title 't critical {:.4g}'",
                                     gpString("Pareto chart of standardised effects: " + r.response), rs, r.tCritical,
                                     r.tCritical)));
    // predicted vs actual and normal plot of residuals
    std::string pa;
    std::vector<double> res;
    for (const auto& d : r.diagnostics) {
      pa += fmt::format("{:.10g} {:.10g}\n", d.actual, d.predicted);
      res.push_back(std::isfinite(d.externallyStudentized) ? d.externallyStudentized : d.studentized);
    }
    writeData(dir, "pred_actual_" + rs + ".dat", pa);
    append(files, render(dir, "pred_actual_" + rs,
                         fmt::format("set title {}\nset xlabel 'Actual'\nset ylabel 'Predicted'\nset key left\n"
                                     "plot 'pred_actual_{}.dat' using 1:2 with points pt 7 title 'runs', x with lines "
                                     "title 'y = x'",
                                     gpString("Predicted vs actual: " + r.response), rs)));
    res.erase(std::remove_if(res.begin(), res.end(), [](double v) { return !std::isfinite(v); }), res.end());
    std::sort(res.begin(), res.end());
    std::string np;
    for (std::size_t i = 0; i < res.size(); ++i)
      np += fmt::format("{:.10g} {:.10g}\n", res[i], normalQuantile((i + 0.5) / static_cast<double>(res.size())));
    writeData(dir, "normal_" + rs + ".dat", np);
    append(files, render(dir, "normal_" + rs,
                         fmt::format("set title {}\nset xlabel 'Externally studentized residual'\n"
                                     "set ylabel 'Normal quantile'\nset key left\nplot 'normal_{}.dat' using 1:2 "
                                     "with points pt 7 title 'residuals', x with lines title 'reference'",
                                     gpString("Normal plot of residuals: " + r.response), rs)));
    // surfaces and contours per factor pair (other factors at the centre)
    const int k = static_cast<int>(a.factors.size());
    for (int i = 0; i < k; ++i)
      for (int j = i + 1; j < k; ++j) {
        const std::string base = rs + "_" + safe(a.factors[i].name) + "_" + safe(a.factors[j].name);
        std::string grid;
        constexpr int m = 31;
        for (int u = 0; u < m; ++u) {
          for (int v = 0; v < m; ++v) {
            Eigen::VectorXd x = Eigen::VectorXd::Zero(k);
            x(i) = -1.0 + 2.0 * u / (m - 1);
            x(j) = -1.0 + 2.0 * v / (m - 1);
            grid += fmt::format("{:.10g} {:.10g} {:.10g}\n", a.factors[i].toReal(x(i)), a.factors[j].toReal(x(j)),
                                r.model.predict(r.beta, x));
          }
          grid += "\n";
        }
        writeData(dir, "grid_" + base + ".dat", grid);
        const std::string labels = fmt::format("set xlabel {}\nset ylabel {}\n", gpString(a.factors[i].name),
                                               gpString(a.factors[j].name));
        append(files, render(dir, "surface_" + base,
                             fmt::format("set title {}\n{}set zlabel {}\nset pm3d\nset ticslevel 0\n"
                                         "splot 'grid_{}.dat' using 1:2:3 with pm3d notitle",
                                         gpString("Response surface: " + r.response), labels, gpString(r.response),
                                         base)));
        append(files, render(dir, "contour_" + base,
                             fmt::format("set title {}\n{}set view map\nset contour base\nset cntrparam levels auto 10\n"
                                         "set pm3d at b\nunset surface\nunset clabel\n"
                                         "splot 'grid_{}.dat' using 1:2:3 with pm3d notitle, 'grid_{}.dat' using 1:2:3 "
                                         "with lines nosurface lc rgb 'black' notitle",
                                         gpString("Contours: " + r.response), labels, base, base)));
      }
  }
  return files;
}

std::vector<std::string> plotDesirabilityRamps(const std::string& dir, const std::vector<GoalSpec>& goals) {
  prepare(dir);
  std::vector<std::string> files;
  for (const auto& g : goals) {
    const std::string rs = safe(g.response);
    const double span = g.upper - g.lower;
    std::string dat;
    for (int i = 0; i <= 400; ++i) {
      const double y = g.lower - 0.1 * span + 1.2 * span * i / 400.0;
      dat += fmt::format("{:.10g} {:.10g}\n", y, desirability(g, y));
    }
    writeData(dir, "desirability_" + rs + ".dat", dat);
    append(files, render(dir, "desirability_" + rs,
                         fmt::format("set title {}\nset xlabel {}\nset ylabel 'desirability d'\nset yrange [-0.05:1.05]\n"
                                     "plot 'desirability_{}.dat' using 1:2 with lines lw 2 notitle",
                                     gpString("Desirability ramp (" + goalName(g.goal) + "): " + g.response),
                                     gpString(g.response), rs)));
  }
  return files;
}

}  // namespace paddy::doe
