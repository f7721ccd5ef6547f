// The peer in bench/: CGAL's 2D Delaunay and constrained Delaunay triangulations on the same
// Triangle-format inputs (.node, .poly) that acutemesh reads.
//
//   bench_cgal [--once] [--mode delaunay|cdt] [--cdt-insert auto|indices|polyline] [--repeat N] FILE
//
// Default: reads FILE once with its own fast parser, then times the library call only
// (a fresh triangulation each time), best of 3, and prints one line of key=value pairs.
// --once: read, triangulate once, print counts: for timing the whole process from outside.
// Mode defaults by extension: .node -> delaunay, .poly -> cdt.
//
// Delaunay: Delaunay_triangulation_2 (Epick) built with the range insert, which spatially
// sorts the points first. CDT: Constrained_Delaunay_triangulation_2 (Epick), then the flood
// fill that marks the domain (faces inside the polygon: odd nesting level, as in CGAL's
// polygon_triangulation example), so that the output matches acutemesh's Cdt mode, which
// restricts to the domain. Two ways to insert the constraints:
//   polyline: insert_constraint(first, last, close=true), the polygon's vertices in order, each
//             edge constrained right after its end vertex is inserted;
//   indices:  insert_constraints(points, index pairs): spatial sort, all points, then the
//             constraints; works for any PSLG.
// auto (the default) takes polyline when the segments are the single cycle 0-1-...-(n-1)-0,
// since it is the faster of the two there (about 3x on the 10^5-edge star polygon), else indices.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Dt = CGAL::Delaunay_triangulation_2<K>;

struct FaceInfo {
  int nesting = -1;
  bool inDomain() const { return nesting % 2 == 1; }
};
using Vb = CGAL::Triangulation_vertex_base_2<K>;
using Fbb = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbb>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds>;

[[noreturn]] void die(const std::string& msg) {
  std::fprintf(stderr, "bench_cgal: %s\n", msg.c_str());
  std::exit(2);
}

std::string readFile(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) die("cannot open " + path);
  std::string s;
  std::fseek(f, 0, SEEK_END);
  long n = std::ftell(f);
  std::fseek(f, 0, SEEK_SET);
  s.resize(n > 0 ? size_t(n) : 0);
  if (n > 0 && std::fread(s.data(), 1, s.size(), f) != s.size()) die("cannot read " + path);
  std::fclose(f);
  return s;
}

// Line-oriented tokenizer for Triangle's formats: '#' starts a comment, blank lines skipped.
class Reader {
 public:
  Reader(std::string_view text, std::string name) : t_(text), name_(std::move(name)) {}

  // Moves to the next line with content; false at the end of the text.
  bool nextLine() {
    while (pos_ < t_.size()) {
      size_t end = t_.find('\n', pos_);
      if (end == std::string_view::npos) end = t_.size();
      ++lineNo_;
      std::string_view line = t_.substr(pos_, end - pos_);
      pos_ = end + 1;
      if (size_t h = line.find('#'); h != std::string_view::npos) line = line.substr(0, h);
      size_t a = 0;
      while (a < line.size() && isSpace(line[a])) ++a;
      if (a == line.size()) continue;
      cur_ = line.data() + a;
      end_ = line.data() + line.size();
      return true;
    }
    return false;
  }
  void needLine(const char* what) {
    if (!nextLine()) fail(std::string("unexpected end of file, expected ") + what);
  }
  bool hasToken() {
    skipSpace();
    return cur_ < end_;
  }
  double num() {
    skipSpace();
    double v = 0;
    auto r = std::from_chars(cur_, end_, v);
    if (r.ec != std::errc()) fail("expected a number");
    cur_ = r.ptr;
    return v;
  }
  long long integer() {
    skipSpace();
    long long v = 0;
    auto r = std::from_chars(cur_, end_, v);
    if (r.ec != std::errc()) fail("expected an integer");
    cur_ = r.ptr;
    return v;
  }
  [[noreturn]] void fail(const std::string& what) {
    die(name_ + ":" + std::to_string(lineNo_) + ": " + what);
  }

 private:
  static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == ','; }
  void skipSpace() {
    while (cur_ < end_ && isSpace(*cur_)) ++cur_;
  }
  std::string_view t_;
  std::string name_;
  size_t pos_ = 0;
  size_t lineNo_ = 0;
  const char* cur_ = nullptr;
  const char* end_ = nullptr;
};

struct Input {
  std::vector<Point> points;
  std::vector<std::pair<std::size_t, std::size_t>> segments;
};

// Vertex block shared by .node and .poly: header then "<id> <x> <y> [attrs] [marker]".
long long readVertices(Reader& r, long long n, Input& in) {
  in.points.reserve(size_t(n));
  long long base = 0;
  for (long long i = 0; i < n; ++i) {
    r.needLine("a vertex line");
    long long id = r.integer();
    if (i == 0) base = id;
    double x = r.num(), y = r.num();
    in.points.emplace_back(x, y);
  }
  return base;
}

Input parse(const std::string& path, bool poly) {
  std::string text = readFile(path);
  Reader r(text, path);
  Input in;
  r.needLine("the header");
  long long n = r.integer();
  if (n < 0 || (size_t)n > text.size()) r.fail("bad vertex count");
  if (n == 0) r.fail("vertices in a separate .node file are not supported here");
  long long base = readVertices(r, n, in);
  if (!poly) return in;
  r.needLine("the segment header");
  long long m = r.integer();
  if (m < 0 || (size_t)m > text.size()) r.fail("bad segment count");
  in.segments.reserve(size_t(m));
  for (long long i = 0; i < m; ++i) {
    r.needLine("a segment line");
    r.integer();
    long long a = r.integer() - base, b = r.integer() - base;
    if (a < 0 || b < 0 || a >= n || b >= n) r.fail("segment endpoint out of range");
    in.segments.emplace_back(size_t(a), size_t(b));
  }
  return in;  // holes and regional attributes: not used by this benchmark
}

// True when the segments are exactly the closed polygon 0-1-2-...-(n-1)-0.
bool isSimpleCycleInOrder(const Input& in) {
  size_t n = in.points.size();
  if (in.segments.size() != n || n < 3) return false;
  for (size_t i = 0; i < n; ++i)
    if (in.segments[i].first != i || in.segments[i].second != (i + 1) % n) return false;
  return true;
}

// Marks faces by nesting level (number of constraints crossed from the infinite face),
// breadth-first; the domain is the odd levels. CGAL's polygon_triangulation example.
size_t markDomain(Cdt& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info().nesting = -1;
  std::list<Cdt::Edge> border;
  auto flood = [&](Cdt::Face_handle start, int level) {
    if (start->info().nesting != -1) return;
    std::deque<Cdt::Face_handle> queue;
    queue.push_back(start);
    while (!queue.empty()) {
      Cdt::Face_handle fh = queue.front();
      queue.pop_front();
      if (fh->info().nesting != -1) continue;
      fh->info().nesting = level;
      for (int i = 0; i < 3; ++i) {
        Cdt::Edge e(fh, i);
        Cdt::Face_handle nb = fh->neighbor(i);
        if (nb->info().nesting == -1) {
          if (cdt.is_constrained(e))
            border.push_back(e);
          else
            queue.push_back(nb);
        }
      }
    }
  };
  flood(cdt.infinite_face(), 0);
  while (!border.empty()) {
    Cdt::Edge e = border.front();
    border.pop_front();
    Cdt::Face_handle n = e.first->neighbor(e.second);
    if (n->info().nesting == -1) flood(n, e.first->info().nesting + 1);
  }
  size_t inside = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info().inDomain()) ++inside;
  return inside;
}

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  bool once = false;
  std::string mode, insertHow = "auto", file;
  int repeat = 3;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--once") once = true;
    else if (a == "--mode" && i + 1 < argc) mode = argv[++i];
    else if (a == "--cdt-insert" && i + 1 < argc) insertHow = argv[++i];
    else if (a == "--repeat" && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
    else if (!a.empty() && a[0] != '-' && file.empty()) file = a;
    else die("usage: bench_cgal [--once] [--mode delaunay|cdt] [--cdt-insert auto|indices|polyline] [--repeat N] FILE");
  }
  if (file.empty()) die("no input file");
  bool poly = file.size() > 5 && file.compare(file.size() - 5, 5, ".poly") == 0;
  if (mode.empty()) mode = poly ? "cdt" : "delaunay";
  if (mode != "delaunay" && mode != "cdt") die("unknown mode " + mode);
  if (insertHow != "auto" && insertHow != "indices" && insertHow != "polyline")
    die("unknown --cdt-insert " + insertHow);

  auto t0 = std::chrono::steady_clock::now();
  Input in = parse(file, poly);
  double readMs = msSince(t0);
  if (mode == "cdt" && insertHow == "auto")
    insertHow = isSimpleCycleInOrder(in) ? "polyline" : "indices";
  if (mode == "cdt" && insertHow == "polyline" && !isSimpleCycleInOrder(in))
    die("--cdt-insert polyline needs a single polygon 0-1-...-n-1-0");
  if (once) repeat = 1;

  double best = 1e300, bestDomain = 0;
  size_t faces = 0, vertices = 0, domainFaces = 0;
  for (int r = 0; r < repeat; ++r) {
    if (mode == "delaunay") {
      auto t = std::chrono::steady_clock::now();
      Dt dt;
      dt.insert(in.points.begin(), in.points.end());
      double ms = msSince(t);
      faces = dt.number_of_faces();
      vertices = dt.number_of_vertices();
      best = std::min(best, ms);  // dt's destruction is not timed
    } else {
      auto t = std::chrono::steady_clock::now();
      Cdt cdt;
      if (insertHow == "indices") {
        cdt.insert_constraints(in.points.begin(), in.points.end(), in.segments.begin(),
                               in.segments.end());
      } else {
        cdt.insert_constraint(in.points.begin(), in.points.end(), true);
      }
      double cdtMs = msSince(t);
      auto t2 = std::chrono::steady_clock::now();
      domainFaces = markDomain(cdt);
      double domMs = msSince(t2);
      faces = cdt.number_of_faces();
      vertices = cdt.number_of_vertices();
      if (cdtMs + domMs < best) {
        best = cdtMs + domMs;
        bestDomain = domMs;
      }
    }
  }
  std::printf("tool=cgal mode=%s file=%s vertices=%zu triangles=%zu", mode.c_str(), file.c_str(),
              vertices, mode == "cdt" ? domainFaces : faces);
  if (mode == "cdt") std::printf(" all_faces=%zu insert=%s", faces, insertHow.c_str());
  std::printf(" read_ms=%.1f", readMs);
  if (once) {
    std::printf(" ms=%.1f", best);
  } else {
    std::printf(" best_ms=%.1f repeat=%d", best, repeat);
  }
  if (mode == "cdt") std::printf(" domain_ms=%.1f", bestDomain);
  std::printf("\n");
  return 0;
}
