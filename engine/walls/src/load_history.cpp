// Load history CSV writer: written to <path>.tmp, then renamed over <path> (atomic on POSIX).
#include <paddy/errors.hpp>
#include <paddy/geometry/load_history.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace paddy::geometry {

void writeLoadHistoryCsv(const std::string& path, const std::vector<LoadSample>& samples, const std::string& wall_name) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::trunc);
    if (!f) throw InputError(path + ": cannot open for writing");
    f.precision(10);
    if (!wall_name.empty()) f << "# wall: " << wall_name << "\n";
    f << "t,Fx,Fy,Fz,Tx,Ty,Tz,T_axis,distance,angle\n";
    for (const LoadSample& s : samples)
      f << s.t << ',' << s.force.x() << ',' << s.force.y() << ',' << s.force.z() << ',' << s.torque.x() << ','
        << s.torque.y() << ',' << s.torque.z() << ',' << s.axial_torque << ',' << s.distance << ',' << s.angle << '\n';
    if (!f) throw InputError(path + ": write failed");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw InputError(path + ": cannot rename " + tmp + ": " + ec.message());
}

}  // namespace paddy::geometry
