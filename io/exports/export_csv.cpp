#include "io/exports/export_csv.h"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "io/output/atomic_output.h"
#include "io/output/output_set.h"
#include "io/output/temporary_names.h"
#include "io/text/csv_number.h"
#include "io/format_error.h"
#include "io/imports/import_nav_csv.h"
#include "io/files/sensor_model_yaml.h"
#include "io/time/utc_time.h"

namespace gesmi::io {
namespace {

namespace fs = std::filesystem;

// One CSV row built in a reused buffer: the 10^7-row exports stay fast.
class Row {
 public:
  explicit Row(std::ostream& out) : out_(out) {}
  Row& operator<<(double x) {
    if (!line_.empty()) line_ += ',';
    append_number(line_, x);  // shortest exact form
    return *this;
  }
  Row& text(std::string_view s) {
    if (!line_.empty()) line_ += ',';
    line_ += s;
    return *this;
  }
  void end() {
    line_ += '\n';
    out_.write(line_.data(), static_cast<std::streamsize>(line_.size()));
    line_.clear();
  }

 private:
  std::ostream& out_;
  std::string line_;
};

void write_file(const fs::path& path, void (*writer)(const Mission&, std::ostream&), const Mission& m) {
  write_text_file(path.string(), [&](std::ostream& out) { writer(m, out); });
}

}  // namespace

void write_text_file(const std::string& path, const std::function<void(std::ostream&)>& writer) {
  AtomicOutput file(path);
  {
    std::ofstream out(file.temp_path(), std::ios::binary);
    if (!out) throw FormatError(path + ": cannot create the file: " + std::strerror(errno));
    writer(out);
    out.flush();
    if (!out) throw FormatError(path + ": cannot write (disk full?)");
  }
  file.commit();
}

void write_nav_csv(const Mission& m, std::ostream& out) {
  std::string header = "time,roll,pitch,heading,vx,vy,vz,altitude,depth";
  std::vector<const std::vector<double>*> bounds;
  for (const NavHalfWidthColumn& c : nav_half_width_columns())
    if (!(m.half_widths.*c.member).empty()) {
      header += "," + std::string(c.name);
      bounds.push_back(&(m.half_widths.*c.member));
    }
  out << header << '\n';
  Row row(out);
  for (std::size_t k = 0; k < m.size(); ++k) {
    row << m.time[k] << m.roll[k] << m.pitch[k] << m.heading[k] << m.vx[k] << m.vy[k] << m.vz[k] << m.altitude[k]
        << m.depth[k];
    for (const std::vector<double>* b : bounds) row << (*b)[k];
    row.end();
  }
}

void write_gps_csv(const Mission& m, std::ostream& out) {
  const bool given = !m.gps_given_north_halfwidth.empty();
  out << "time,longitude,latitude" << (given ? ",north_halfwidth,east_halfwidth" : "") << '\n';
  Row row(out);
  for (std::size_t i = 0; i < m.gps_time.size(); ++i) {
    row << m.gps_time[i] << m.gps_longitude[i] << m.gps_latitude[i];
    if (given) row << m.gps_given_north_halfwidth[i] << m.gps_given_east_halfwidth[i];
    row.end();
  }
}

void write_marks_csv(const Mission& m, std::ostream& out) {
  out << "time,mine,range,side\n";
  Row row(out);
  for (std::size_t j = 0; j < m.mark_count(); ++j) {
    row << m.mark_time[j];
    row.text(m.mark_mine[j] < 0 ? std::string("?") : std::to_string(m.mark_mine[j]));
    row << m.mark_range[j];
    row.text(m.mark_side[j] > 0 ? "starboard" : "port");
    row.end();
  }
}

void write_truth_csv(const Mission& m, std::ostream& out) {
  out << "time,north,east,down\n";
  Row row(out);
  for (std::size_t k = 0; k < m.truth_x.size(); ++k) {
    row << m.time[k] << m.truth_x[k] << m.truth_y[k] << m.truth_z[k];
    row.end();
  }
}

void write_truth_mines_csv(const Mission& m, std::ostream& out) {
  out << "mine,north,east,down\n";
  Row row(out);
  for (std::size_t i = 0; 3 * i + 2 < m.truth_mines.size(); ++i) {
    row.text(std::to_string(i));
    row << m.truth_mines[3 * i] << m.truth_mines[3 * i + 1] << m.truth_mines[3 * i + 2];
    row.end();
  }
}

std::vector<std::string> import_arguments(const Mission& m, const std::string& output) {
  std::vector<std::string> args = {"import", "nav", "nav.csv", "--gps", "gps.csv", "--marks", "marks.csv",
                                   "--config", "model.yaml", "--origin",
                                   format_number(m.origin.latitude) + "," + format_number(m.origin.longitude),
                                   "--mines", std::to_string(m.mine_count)};
  if (m.has_truth()) args.insert(args.end(), {"--truth", "truth.csv"});
  if (!m.truth_mines.empty()) args.insert(args.end(), {"--truth-mines", "truth_mines.csv"});
  if (m.epoch) args.insert(args.end(), {"--epoch", format_iso8601(*m.epoch)});
  args.insert(args.end(), {"-o", output});
  return args;
}

void check_export_folder(const std::string& folder) {
  if (folder.empty()) throw FormatError("output folder is empty");
  const fs::path target = fs::path(folder).lexically_normal();
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(parent, ec)) throw FormatError(folder + ": folder " + parent.string() + " does not exist");
  if (::access(parent.c_str(), W_OK) != 0) throw FormatError(folder + ": folder " + parent.string() + " is not writable");
  if (fs::exists(target, ec)) {
    if (!fs::is_directory(target, ec)) throw FormatError(folder + ": exists and is not a folder");
    remove_dead_temporaries(target);  // what a killed export left
    if (!fs::is_empty(target, ec)) throw FormatError(folder + ": the folder exists and is not empty (choose a new one)");
  }
}

void export_mission_csv(const Mission& m, const std::string& folder) {
  check_export_folder(folder);
  const fs::path target = fs::path(folder).lexically_normal();
  create_output_folder(folder);
  write_file(target / "nav.csv", write_nav_csv, m);
  write_file(target / "gps.csv", write_gps_csv, m);
  write_file(target / "marks.csv", write_marks_csv, m);
  if (m.has_truth()) write_file(target / "truth.csv", write_truth_csv, m);
  if (!m.truth_mines.empty()) write_file(target / "truth_mines.csv", write_truth_mines_csv, m);
  write_file(target / "model.yaml", [](const Mission& mission, std::ostream& out) { out << sensor_model_yaml(mission.model); }, m);
  write_file(target / "import-command.txt", [](const Mission& mission, std::ostream& out) {
    out << "gesmi";
    for (const std::string& a : import_arguments(mission, "mission.h5")) out << ' ' << a;
    out << '\n';
  }, m);
}

}  // namespace gesmi::io
