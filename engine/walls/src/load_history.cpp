// Load history CSV writer: written to a temporary file, then renamed over <path> (atomic on POSIX).
#include <paddy/errors.hpp>
#include <paddy/geometry/load_history.hpp>
#include <paddy/io/atomic_file.hpp>

#include <sstream>

namespace paddy::geometry {

void writeLoadHistoryCsv(const std::string& path, const std::vector<LoadSample>& samples, const std::string& wall_name) {
  std::ostringstream f;
  f.precision(10);
  if (!wall_name.empty()) f << "# wall: " << wall_name << "\n";
  f << "t,Fx,Fy,Fz,Tx,Ty,Tz,T_axis,distance,angle\n";
  for (const LoadSample& s : samples)
    f << s.t << ',' << s.force.x() << ',' << s.force.y() << ',' << s.force.z() << ',' << s.torque.x() << ','
      << s.torque.y() << ',' << s.torque.z() << ',' << s.axial_torque << ',' << s.distance << ',' << s.angle << '\n';
  io::writeFileAtomic(path, f.str());  // errors name the file and the cause
}

}  // namespace paddy::geometry
