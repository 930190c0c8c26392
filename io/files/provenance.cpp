#include "io/files/provenance.h"

#include <chrono>
#include <filesystem>
#include <map>
#include <optional>

#include "io/digest/digest.h"
#include "io/io_version.h"
#include "io/output/output_set.h"
#include "io/time/utc_time.h"

namespace gesmi::io {
namespace {

std::string& command_line() {
  static std::string line = "(gesmi library)";
  return line;
}

// Shell-quoted when needed, so the line can be pasted back.
std::string quoted(const std::string& word) {
  if (!word.empty() && word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_./=:,+@%") ==
                           std::string::npos)
    return word;
  std::string out = "'";
  for (const char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// Each input is hashed once per process (a demo's steps read the same mission).
const std::string& file_digest(const std::string& path) {
  static std::map<std::string, std::string> digests;
  auto it = digests.find(path);
  if (it == digests.end()) it = digests.emplace(path, sha256_of_file(path)).first;
  return it->second;
}

}  // namespace

void set_command_line(std::span<const std::string> arguments) {
  std::string line = "gesmi";
  for (const std::string& a : arguments) line += " " + quoted(a);
  command_line() = line;
}

void write_time_units(H5File& f, const std::string& dataset, const std::string& long_name,
                      const std::optional<std::int64_t>& epoch) {
  if (f.kind(dataset) != H5Kind::dataset) return;
  f.set_attribute(dataset, "units", epoch ? "seconds since " + format_iso8601(*epoch) : std::string("s"));
  f.set_attribute(dataset, "standard_name", std::string("time"));
  f.set_attribute(dataset, "long_name", long_name);
}

void write_provenance(H5File& f, std::string_view feature_type) {
  const auto now = std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch());
  const std::string created = format_iso8601(now.count());
  // A result records its version among the attributes its digest covers, before this.
  if (!f.string_attribute("/", "gesmi_version")) f.set_attribute("/", "gesmi_version", std::string(version()));
  f.set_attribute("/", "command_line", command_line());
  f.set_attribute("/", "created_utc", created);
  f.set_attribute("/", "source", "gesmi " + std::string(version()));
  f.set_attribute("/", "history", created + ": " + command_line());
  if (!feature_type.empty()) f.set_attribute("/", "featureType", std::string(feature_type));
  f.create_group("/provenance");
  const std::vector<std::string> inputs = OutputSet::open_inputs();
  f.set_attribute("/provenance", "input_count", static_cast<std::int64_t>(inputs.size()));
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const std::string name = "input_" + std::to_string(i);
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(inputs[i], ec);
    f.set_attribute("/provenance", name, ec ? inputs[i] : absolute.lexically_normal().string());
    f.set_attribute("/provenance", name + "_sha256", file_digest(inputs[i]));
  }
}

void write_origin(H5File& f, const GeoOrigin& origin) {
  f.set_attribute("/", "origin_latitude", origin.latitude);
  f.set_attribute("/", "origin_longitude", origin.longitude);
  f.set_attribute("/", "datum", std::string(kDatum));
}

void write_units(H5File& f, std::span<const DatasetUnits> table) {
  for (const DatasetUnits& d : table)
    if (f.kind(d.dataset) == H5Kind::dataset) {
      f.set_attribute(d.dataset, "units", std::string(d.units));
      f.set_attribute(d.dataset, "long_name", std::string(d.long_name));
    }
}

}  // namespace gesmi::io
