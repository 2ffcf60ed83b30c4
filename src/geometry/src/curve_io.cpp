#include "ek/geometry/curve_io.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string_view>
#include <vector>

#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"

namespace ek {
namespace {

std::string extension_of(const std::string& path) {
  auto dot = path.find_last_of('.');
  auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::vector<std::string_view> split_ws(std::string_view line) {
  std::vector<std::string_view> tokens;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    size_t j = i;
    while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
    if (j > i) tokens.push_back(line.substr(i, j - i));
    i = j;
  }
  return tokens;
}

double parse_double(std::string_view token, const std::string& where) {
  double value = 0.0;
  const char* begin = token.data();
  const char* end = token.data() + token.size();
  if (!token.empty() && *begin == '+') ++begin;
  auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr != end)
    throw InputError(where + ": '" + std::string(token) + "' is not a number");
  if (!std::isfinite(value))
    throw InputError(where + ": coordinate '" + std::string(token) + "' is not finite");
  return value;
}

long parse_index(std::string_view token, const std::string& where) {
  // OBJ element references may carry "/vt/vn" suffixes; keep the vertex part.
  auto slash = token.find('/');
  if (slash != std::string_view::npos) token = token.substr(0, slash);
  long value = 0;
  auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec != std::errc() || ptr != token.data() + token.size())
    throw InputError(where + ": '" + std::string(token) + "' is not a vertex index");
  return value;
}

/// Orders the vertices along the cycle formed by the OBJ l-elements.
std::vector<int> order_from_lines(const std::vector<std::pair<int, int>>& edges, int n,
                                  const std::string& source) {
  std::vector<std::vector<int>> adj(static_cast<size_t>(n));
  for (auto [a, b] : edges) {
    if (a == b) throw InputError(source + ": l-element joins vertex " + std::to_string(a + 1) + " to itself");
    adj[static_cast<size_t>(a)].push_back(b);
    adj[static_cast<size_t>(b)].push_back(a);
  }
  int ends = 0;
  for (int v = 0; v < n; ++v) {
    auto deg = adj[static_cast<size_t>(v)].size();
    if (deg == 0)
      throw InputError(source + ": vertex " + std::to_string(v + 1) + " is on no l-element");
    if (deg > 2)
      throw InputError(source + ": vertex " + std::to_string(v + 1) + " is on " + std::to_string(deg) +
                       " l-element edges; expected one closed curve");
    if (deg == 1) ++ends;
  }
  if (ends != 0 && ends != 2)
    throw InputError(source + ": l-elements form several curves; expected one closed curve");
  int start = 0;
  if (ends == 2)
    for (int v = 0; v < n; ++v)
      if (adj[static_cast<size_t>(v)].size() == 1) {
        start = v;
        break;
      }
  std::vector<int> order;
  order.reserve(static_cast<size_t>(n));
  std::vector<char> seen(static_cast<size_t>(n), 0);
  int prev = -1, cur = start;
  while (cur >= 0 && !seen[static_cast<size_t>(cur)]) {
    seen[static_cast<size_t>(cur)] = 1;
    order.push_back(cur);
    int next = -1;
    for (int w : adj[static_cast<size_t>(cur)])
      if (w != prev && !seen[static_cast<size_t>(w)]) {
        next = w;
        break;
      }
    prev = cur;
    cur = next;
  }
  if (static_cast<int>(order.size()) != n)
    throw InputError(source + ": l-elements form several curves; expected one closed curve");
  return order;
}

}  // namespace

void validate_closed_curve(const Points& P, const std::string& source) {
  const auto n = P.rows();
  if (n < 4)
    throw InputError(source + ": a closed curve needs at least 4 vertices, got " + std::to_string(n));
  for (Eigen::Index i = 0; i < n; ++i)
    if (!P.row(i).allFinite())
      throw InputError(source + ": vertex " + std::to_string(i + 1) + " has a coordinate that is not finite");
  const double diag = (P.colwise().maxCoeff() - P.colwise().minCoeff()).norm();
  for (Eigen::Index i = 0; i < n; ++i) {
    Eigen::Index j = (i + 1) % n;
    if ((P.row(j) - P.row(i)).norm() <= 1e-12 * diag)
      throw InputError(source + ": vertices " + std::to_string(i + 1) + " and " + std::to_string(j + 1) +
                       " coincide (zero-length edge)");
  }
}

Points parse_curve(const std::string& text, const std::string& format, const std::string& source) {
  std::vector<Vec3> vertices;
  std::vector<std::pair<int, int>> edges;
  std::vector<long> raw_line_refs;  // checked after all vertices are known
  std::vector<int> raw_line_numbers;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  const bool obj = (format == "obj");
  if (!obj && format != "txt")
    throw InputError(source + ": unknown curve format '" + format + "' (expected .obj or .txt)");
  while (std::getline(in, line)) {
    ++line_no;
    const std::string where = source + ":" + std::to_string(line_no);
    auto tokens = split_ws(line);
    if (tokens.empty() || tokens[0][0] == '#') continue;
    if (obj) {
      if (tokens[0] == "v") {
        if (tokens.size() != 4 && tokens.size() != 5)
          throw InputError(where + ": vertex line needs 3 coordinates, got " + std::to_string(tokens.size() - 1));
        vertices.emplace_back(parse_double(tokens[1], where), parse_double(tokens[2], where),
                              parse_double(tokens[3], where));
      } else if (tokens[0] == "l") {
        if (tokens.size() < 3) throw InputError(where + ": l-element needs at least 2 vertex indices");
        long prev = 0;
        for (size_t k = 1; k < tokens.size(); ++k) {
          long idx = parse_index(tokens[k], where);
          if (k > 1) {
            raw_line_refs.push_back(prev);
            raw_line_refs.push_back(idx);
            raw_line_numbers.push_back(line_no);
          }
          prev = idx;
        }
      } else if (tokens[0] == "f") {
        throw InputError(where + ": faces are not curves (expected v and l lines)");
      }
      // o, g, s, vn, vt, mtllib, usemtl: ignored.
    } else {
      if (tokens.size() != 3)
        throw InputError(where + ": expected 3 coordinates 'x y z', got " + std::to_string(tokens.size()) +
                         " fields");
      vertices.emplace_back(parse_double(tokens[0], where), parse_double(tokens[1], where),
                            parse_double(tokens[2], where));
    }
  }
  if (vertices.empty()) throw InputError(source + ": no vertices");
  const int n = static_cast<int>(vertices.size());
  std::vector<int> order;
  if (!raw_line_refs.empty()) {
    for (size_t k = 0; k < raw_line_refs.size(); k += 2) {
      const std::string where = source + ":" + std::to_string(raw_line_numbers[k / 2]);
      int ab[2];
      for (int s = 0; s < 2; ++s) {
        long idx = raw_line_refs[k + static_cast<size_t>(s)];
        if (idx < 0) idx = n + idx + 1;  // OBJ negative (relative) indices
        if (idx < 1 || idx > n)
          throw InputError(where + ": vertex index " + std::to_string(raw_line_refs[k + static_cast<size_t>(s)]) +
                           " out of range 1.." + std::to_string(n));
        ab[s] = static_cast<int>(idx - 1);
      }
      edges.emplace_back(ab[0], ab[1]);
    }
    // Drop duplicate edges (a closed polyline listed in both directions).
    std::set<std::pair<int, int>> seen_edges;
    std::vector<std::pair<int, int>> unique_edges;
    for (auto e : edges)
      if (seen_edges.insert(std::minmax(e.first, e.second)).second) unique_edges.push_back(e);
    order = order_from_lines(unique_edges, n, source);
  } else {
    order.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) order[static_cast<size_t>(i)] = i;
  }
  int m = n;
  if (m >= 2 && vertices[static_cast<size_t>(order.front())] == vertices[static_cast<size_t>(order.back())]) --m;
  Points P(m, 3);
  for (int i = 0; i < m; ++i) P.row(i) = vertices[static_cast<size_t>(order[static_cast<size_t>(i)])].transpose();
  validate_closed_curve(P, source);
  return P;
}

Points read_curve(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext != "obj" && ext != "txt")
    throw InputError(path + ": unknown curve format '." + ext + "' (expected .obj or .txt)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError(path + ": read error");
  return parse_curve(buffer.str(), ext, path);
}

void write_curve(const std::string& path, const Points& P) {
  const std::string ext = extension_of(path);
  if (ext != "obj" && ext != "txt")
    throw InputError(path + ": unknown curve format '." + ext + "' (expected .obj or .txt)");
  AtomicFile file(path);
  auto& out = file.stream();
  char buf[128];
  const auto n = P.rows();
  if (ext == "obj") out << "# closed curve, " << n << " vertices (last joined to first)\n";
  for (Eigen::Index i = 0; i < n; ++i) {
    std::snprintf(buf, sizeof buf, "%s%.17g %.17g %.17g\n", ext == "obj" ? "v " : "", P(i, 0), P(i, 1), P(i, 2));
    out << buf;
  }
  if (ext == "obj")
    for (Eigen::Index i = 0; i < n; ++i) out << "l " << (i + 1) << ' ' << ((i + 1) % n + 1) << '\n';
  file.commit();
}

}  // namespace ek
