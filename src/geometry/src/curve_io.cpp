#include "ek/geometry/curve_io.hpp"

#include "ek/geometry/link.hpp"

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

namespace {

/// A curve file's content: its vertices, its l-elements' edges (0-based,
/// checked, duplicates dropped) and, for .txt, where each blank-line
/// separated block of vertices begins.
struct RawCurve {
  std::vector<Vec3> vertices;
  std::vector<std::pair<int, int>> edges;
  std::vector<int> blocks;  ///< .txt: first vertex of each block (blocks[0] = 0)
};

/// The l-element references (1-based, negative = relative) resolved and checked.
std::vector<std::pair<int, int>> resolve_edges(const std::vector<long>& refs, const std::vector<int>& line_numbers,
                                               int n, const std::string& source) {
  std::vector<std::pair<int, int>> edges;
  for (size_t k = 0; k < refs.size(); k += 2) {
    const std::string where = source + ":" + std::to_string(line_numbers[k / 2]);
    int ab[2];
    for (int s = 0; s < 2; ++s) {
      long idx = refs[k + static_cast<size_t>(s)];
      if (idx < 0) idx = n + idx + 1;  // OBJ negative (relative) indices
      if (idx < 1 || idx > n)
        throw InputError(where + ": vertex index " + std::to_string(refs[k + static_cast<size_t>(s)]) +
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
  return unique_edges;
}

/// One OBJ line into `raw` (v and l lines; f refused; others ignored).
void parse_obj_line(const std::vector<std::string_view>& tokens, const std::string& where, int line_no,
                    RawCurve& raw, std::vector<long>& refs, std::vector<int>& ref_lines) {
  if (tokens[0] == "v") {
    if (tokens.size() != 4 && tokens.size() != 5)
      throw InputError(where + ": vertex line needs 3 coordinates, got " + std::to_string(tokens.size() - 1));
    raw.vertices.emplace_back(parse_double(tokens[1], where), parse_double(tokens[2], where),
                              parse_double(tokens[3], where));
  } else if (tokens[0] == "l") {
    if (tokens.size() < 3) throw InputError(where + ": l-element needs at least 2 vertex indices");
    long prev = 0;
    for (size_t k = 1; k < tokens.size(); ++k) {
      const long idx = parse_index(tokens[k], where);
      if (k > 1) {
        refs.push_back(prev);
        refs.push_back(idx);
        ref_lines.push_back(line_no);
      }
      prev = idx;
    }
  } else if (tokens[0] == "f") {
    throw InputError(where + ": faces are not curves (expected v and l lines)");
  }
  // o, g, s, vn, vt, mtllib, usemtl: ignored.
}

RawCurve parse_raw(const std::string& text, const std::string& format, const std::string& source) {
  RawCurve raw;
  std::vector<long> refs;  // checked after all vertices are known
  std::vector<int> ref_lines;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  const bool obj = (format == "obj");
  if (!obj && format != "txt")
    throw InputError(source + ": unknown curve format '" + format + "' (expected .obj or .txt)");
  bool block_open = false;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string where = source + ":" + std::to_string(line_no);
    auto tokens = split_ws(line);
    if (tokens.empty()) block_open = false;
    if (tokens.empty() || tokens[0][0] == '#') continue;
    if (obj) {
      parse_obj_line(tokens, where, line_no, raw, refs, ref_lines);
      continue;
    }
    if (tokens.size() != 3)
      throw InputError(where + ": expected 3 coordinates 'x y z', got " + std::to_string(tokens.size()) + " fields");
    if (!block_open) raw.blocks.push_back(static_cast<int>(raw.vertices.size()));
    block_open = true;
    raw.vertices.emplace_back(parse_double(tokens[0], where), parse_double(tokens[1], where),
                              parse_double(tokens[2], where));
  }
  if (raw.vertices.empty()) throw InputError(source + ": no vertices");
  raw.edges = resolve_edges(refs, ref_lines, static_cast<int>(raw.vertices.size()), source);
  return raw;
}

/// The polygon through `vertices[order]`, an explicit closing vertex dropped, validated.
Points closed_polygon(const std::vector<Vec3>& vertices, const std::vector<int>& order, const std::string& source) {
  auto m = static_cast<int>(order.size());
  if (m >= 2 && vertices[static_cast<size_t>(order.front())] == vertices[static_cast<size_t>(order.back())]) --m;
  Points P(m, 3);
  for (int i = 0; i < m; ++i) P.row(i) = vertices[static_cast<size_t>(order[static_cast<size_t>(i)])].transpose();
  validate_closed_curve(P, source);
  return P;
}

/// The connected components of the l-element graph, each as the sorted list
/// of its vertices, ordered by their lowest vertex.
std::vector<std::vector<int>> edge_components(const std::vector<std::pair<int, int>>& edges, int n) {
  std::vector<int> parent(static_cast<size_t>(n));
  for (int v = 0; v < n; ++v) parent[static_cast<size_t>(v)] = v;
  const auto find = [&](int v) {
    while (parent[static_cast<size_t>(v)] != v) v = parent[static_cast<size_t>(v)] = parent[static_cast<size_t>(parent[static_cast<size_t>(v)])];
    return v;
  };
  for (auto [a, b] : edges) parent[static_cast<size_t>(find(a))] = find(b);
  std::vector<std::vector<int>> out;
  std::vector<int> slot(static_cast<size_t>(n), -1);
  for (int v = 0; v < n; ++v) {
    int& k = slot[static_cast<size_t>(find(v))];
    if (k < 0) {
      k = static_cast<int>(out.size());
      out.emplace_back();
    }
    out[static_cast<size_t>(k)].push_back(v);
  }
  return out;
}

/// One component of the l-element graph as a polygon: its edges relabelled
/// onto 0..size-1 and ordered by order_from_lines().
Points obj_component(const RawCurve& raw, const std::vector<int>& members, int index, const std::string& source) {
  std::vector<int> local(raw.vertices.size(), -1);
  for (size_t k = 0; k < members.size(); ++k) local[static_cast<size_t>(members[k])] = static_cast<int>(k);
  std::vector<std::pair<int, int>> edges;
  for (auto [a, b] : raw.edges)
    if (local[static_cast<size_t>(a)] >= 0) edges.emplace_back(local[static_cast<size_t>(a)], local[static_cast<size_t>(b)]);
  const std::string where = source + " (component " + std::to_string(index + 1) + ")";
  std::vector<int> order = order_from_lines(edges, static_cast<int>(members.size()), where);
  for (int& v : order) v = members[static_cast<size_t>(v)];
  return closed_polygon(raw.vertices, order, where);
}

/// Every vertex on one or two l-element edges (file numbering in messages).
void check_degrees(const std::vector<std::pair<int, int>>& edges, int n, const std::string& source) {
  std::vector<int> degree(static_cast<size_t>(n), 0);
  for (auto [a, b] : edges) {
    if (a == b) throw InputError(source + ": l-element joins vertex " + std::to_string(a + 1) + " to itself");
    ++degree[static_cast<size_t>(a)];
    ++degree[static_cast<size_t>(b)];
  }
  for (int v = 0; v < n; ++v) {
    const int d = degree[static_cast<size_t>(v)];
    if (d == 0) throw InputError(source + ": vertex " + std::to_string(v + 1) + " is on no l-element");
    if (d > 2)
      throw InputError(source + ": vertex " + std::to_string(v + 1) + " is on " + std::to_string(d) +
                       " l-element edges; expected closed curves");
  }
}

/// The vertex order of a one-component file: the l-elements' cycle, or the file's order.
std::vector<int> single_order(const RawCurve& raw, const std::string& source) {
  const int n = static_cast<int>(raw.vertices.size());
  if (!raw.edges.empty()) return order_from_lines(raw.edges, n, source);
  std::vector<int> order(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) order[static_cast<size_t>(i)] = i;
  return order;
}

}  // namespace

Points parse_curve(const std::string& text, const std::string& format, const std::string& source) {
  const RawCurve raw = parse_raw(text, format, source);
  return closed_polygon(raw.vertices, single_order(raw, source), source);
}

Link parse_link(const std::string& text, const std::string& format, const std::string& source) {
  const RawCurve raw = parse_raw(text, format, source);
  const int n = static_cast<int>(raw.vertices.size());
  Link link;
  if (format == "obj" && !raw.edges.empty()) {
    check_degrees(raw.edges, n, source);
    const auto parts = edge_components(raw.edges, n);
    if (parts.size() == 1) return {closed_polygon(raw.vertices, single_order(raw, source), source)};
    for (size_t k = 0; k < parts.size(); ++k) link.push_back(obj_component(raw, parts[k], static_cast<int>(k), source));
  } else if (format == "txt" && raw.blocks.size() > 1) {
    for (size_t k = 0; k < raw.blocks.size(); ++k) {
      const int end = k + 1 < raw.blocks.size() ? raw.blocks[k + 1] : n;
      std::vector<int> order;
      for (int v = raw.blocks[k]; v < end; ++v) order.push_back(v);
      link.push_back(closed_polygon(raw.vertices, order, source + " (component " + std::to_string(k + 1) + ")"));
    }
  } else {
    link.push_back(closed_polygon(raw.vertices, single_order(raw, source), source));
  }
  validate_link(link, source);
  return link;
}

namespace {

/// The text of a curve file and its format ("obj" or "txt", by extension).
std::pair<std::string, std::string> read_text(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext != "obj" && ext != "txt")
    throw InputError(path + ": unknown curve format '." + ext + "' (expected .obj or .txt)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError(path + ": read error");
  return {buffer.str(), ext};
}

}  // namespace

Points read_curve(const std::string& path) {
  const auto [text, ext] = read_text(path);
  return parse_curve(text, ext, path);
}

Points read_vectors(const std::string& path) {
  const auto [text, ext] = read_text(path);
  const RawCurve raw = parse_raw(text, ext, path);
  Points V(static_cast<Eigen::Index>(raw.vertices.size()), 3);
  for (size_t i = 0; i < raw.vertices.size(); ++i) V.row(static_cast<Eigen::Index>(i)) = raw.vertices[i].transpose();
  if (!V.allFinite()) throw InputError(path + ": non-finite coordinates");
  return V;
}

Link read_link(const std::string& path) {
  const auto [text, ext] = read_text(path);
  return parse_link(text, ext, path);
}

void write_curve(const std::string& path, const Points& P) { write_link(path, Link{P}); }

void write_link(const std::string& path, const Link& link) {
  const std::string ext = extension_of(path);
  if (ext != "obj" && ext != "txt")
    throw InputError(path + ": unknown curve format '." + ext + "' (expected .obj or .txt)");
  AtomicFile file(path);
  auto& out = file.stream();
  char buf[128];
  const bool obj = ext == "obj";
  Eigen::Index total = 0;
  for (const Points& P : link) total += P.rows();
  if (obj && link.size() == 1) out << "# closed curve, " << total << " vertices (last joined to first)\n";
  if (obj && link.size() > 1)
    out << "# link, " << link.size() << " closed components, " << total << " vertices (one l loop each)\n";
  for (size_t c = 0; c < link.size(); ++c) {
    if (!obj && c > 0) out << "\n";
    for (Eigen::Index i = 0; i < link[c].rows(); ++i) {
      std::snprintf(buf, sizeof buf, "%s%.17g %.17g %.17g\n", obj ? "v " : "", link[c](i, 0), link[c](i, 1),
                    link[c](i, 2));
      out << buf;
    }
  }
  Eigen::Index first = 1;
  for (const Points& P : link) {
    const Eigen::Index n = P.rows();
    if (obj)
      for (Eigen::Index i = 0; i < n; ++i) out << "l " << (first + i) << ' ' << (first + (i + 1) % n) << '\n';
    first += n;
  }
  file.commit();
}

}  // namespace ek
