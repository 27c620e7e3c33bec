// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// point_set_curvatures INPUT OUTPUT [options]
//
// Command-line front end of the package: reads a point cloud (.xyz/.pwn, .ply, .off) with
// CGAL's point set IO, estimates normals if the file has none, estimates curvatures at
// every point and writes them (.ply or .csv), every input point in input order.
// Run with --help for the options. Exit status: 0 on success, 2 on invalid arguments or
// unreadable/malformed/unwritable files (one line on stderr, no output file left behind),
// 130 when interrupted (Ctrl-C), 1 on unexpected failures.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>

#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/estimate_apss_curvatures.h>
#include <CGAL/estimate_aso_curvatures.h>
// The baseline estimators, when the package has them (same signatures as the ones above).
#if __has_include(<CGAL/estimate_barycenter_curvatures.h>)
#include <CGAL/estimate_barycenter_curvatures.h>
#define PSC_TOOL_HAS_BARYCENTER 1
#endif
#if __has_include(<CGAL/estimate_pca_plane_curvatures.h>)
#include <CGAL/estimate_pca_plane_curvatures.h>
#define PSC_TOOL_HAS_PCA_PLANE 1
#endif
#if __has_include(<CGAL/estimate_pss_curvatures.h>)
#include <CGAL/estimate_pss_curvatures.h>
#define PSC_TOOL_HAS_PSS 1
#endif
#if __has_include(<CGAL/estimate_jet_curvatures.h>)
#include <CGAL/estimate_jet_curvatures.h>
#define PSC_TOOL_HAS_JET 1
#endif
#if __has_include(<CGAL/estimate_vcm_curvatures.h>)
#include <CGAL/estimate_vcm_curvatures.h>
#define PSC_TOOL_HAS_VCM 1
#endif
#if __has_include(<CGAL/estimate_wavejet_curvatures.h>)
#include <CGAL/estimate_wavejet_curvatures.h>
#define PSC_TOOL_HAS_WAVEJET 1
#endif

#include <tbb/global_control.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Point_set_3<Point, Vector> Point_set;
typedef CGAL::Curvature_estimate<Kernel> Estimate;
typedef std::vector<Estimate> Estimates;
typedef std::function<bool(double)> Callback;
namespace PSC = CGAL::Point_set_curvatures;

const char* const program = "point_set_curvatures";

// Every failure the user can fix (arguments, files): one line on stderr, exit status 2.
struct Error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

template <class... T>
std::string cat(const T&... t)
{
  std::ostringstream s;
  (s << ... << t);
  return s.str();
}

// (not named quoted: std::quoted would win by ADL for non-const strings)
std::string in_quotes(const std::string& s) { return "'" + s + "'"; }

std::string lower_extension(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return "";
  std::string e = path.substr(dot);
  for(char& c : e)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// ---------------------------------------------------------------------------------------
// Methods: every estimate_*_curvatures() function of the package with the common signature.

struct Scale
{
  bool by_count = true;
  std::size_t neighbors = 40;  // by count
  double radius = 0;           // by radius, in the unit of the coordinates
  double spacing_multiple = 0; // > 0 for "--radius Nx"
  double spacing = 0;          // CGAL::compute_average_spacing, for "--radius Nx"
};

typedef Estimates (*Run_method)(const Point_set&, const Scale&, const Callback&);

struct Method
{
  const char* name;
  const char* description;
  Run_method run;
};

// One table entry per estimator; the Point_set_3's point and normal maps are the defaults.
#define PSC_TOOL_METHOD(NAME, DESCRIPTION)                                                   \
  Method{#NAME, DESCRIPTION, [](const Point_set& points, const Scale& scale,                 \
                               const Callback& callback) -> Estimates {                      \
           const auto np = CGAL::parameters::callback(callback);                              \
           if(scale.by_count)                                                                 \
             return CGAL::estimate_##NAME##_curvatures<CGAL::Parallel_tag>(                  \
               points, PSC::parameters::neighbor_count(scale.neighbors, np));                 \
           return CGAL::estimate_##NAME##_curvatures<CGAL::Parallel_tag>(points, scale.radius, \
                                                                         np);                 \
         }}

const std::vector<Method>& methods()
{
  static const std::vector<Method> table = {
    PSC_TOOL_METHOD(aso, "Algebraic Shape Operator (Lejemble et al. 2021): full curvature tensor"),
    PSC_TOOL_METHOD(apss, "APSS algebraic sphere: corrected normal and mean curvature only"),
#ifdef PSC_TOOL_HAS_BARYCENTER
    PSC_TOOL_METHOD(barycenter, "baseline: distance to the barycentre"),
#endif
#ifdef PSC_TOOL_HAS_PCA_PLANE
    PSC_TOOL_METHOD(pca_plane, "baseline: distance to the PCA plane"),
#endif
#ifdef PSC_TOOL_HAS_PSS
    PSC_TOOL_METHOD(pss, "baseline: point set surface"),
#endif
#ifdef PSC_TOOL_HAS_JET
    PSC_TOOL_METHOD(jet, "baseline: osculating jet"),
#endif
#ifdef PSC_TOOL_HAS_VCM
    PSC_TOOL_METHOD(vcm, "baseline: Voronoi covariance measure"),
#endif
#ifdef PSC_TOOL_HAS_WAVEJET
    PSC_TOOL_METHOD(wavejet, "baseline: wavejet"),
#endif
  };
  return table;
}

const Method* find_method(const std::string& name)
{
  for(const Method& m : methods())
    if(name == m.name)
      return &m;
  return nullptr;
}

std::string method_names()
{
  std::string s;
  for(const Method& m : methods())
    s += (s.empty() ? "" : "|") + std::string(m.name);
  return s;
}

// ---------------------------------------------------------------------------------------
// Command line

// Quantities that --color can show, and how to read them from an estimate.
const std::map<std::string, double Estimate::*>& color_quantities()
{
  static const std::map<std::string, double Estimate::*> q = {
    {"mean", &Estimate::mean_curvature},     {"gaussian", &Estimate::gaussian_curvature},
    {"k_min", &Estimate::min_curvature},     {"k_max", &Estimate::max_curvature}};
  return q;
}

struct Options
{
  std::string input, output;
  const Method* method = nullptr;
  Scale scale;
  bool radius_given = false, neighbors_given = false;
  int threads = 0;  // 0: every core
  bool quiet = false, ascii = false, require_normals = false, help = false;
  std::string color;  // quantity to colour by, empty for none
};

void print_usage(std::ostream& os)
{
  os << "usage: " << program << " INPUT OUTPUT [options]\n"
     << "\n"
     << "Estimates curvatures at every point of a point cloud.\n"
     << "  INPUT   .xyz or .pwn (x y z [nx ny nz] per line), .ply (ASCII or binary, normals as\n"
     << "          nx ny nz), .off. Without normals, they are estimated (CGAL jet fitting,\n"
     << "          then oriented along a minimum spanning tree) with a warning.\n"
     << "  OUTPUT  .ply (binary unless --ascii) or .csv (with a header line): every input point\n"
     << "          in input order with x y z, the corrected normal nx ny nz, k_min k_max mean\n"
     << "          gaussian, the principal directions dmin_x dmin_y dmin_z dmax_x dmax_y dmax_z\n"
     << "          (doubles; NaN where the estimate is invalid or the method does not provide\n"
     << "          the quantity), neighbors (int) and valid (0 or 1).\n"
     << "\n"
     << "options:\n"
     << "  --method M         estimator: " << method_names() << " (default aso)\n"
     << "  --neighbors K      neighbourhoods by count: each point's radius is the distance to its\n"
     << "                     K-th nearest neighbour, itself counted (default: --neighbors 40)\n"
     << "  --radius R         neighbourhoods of radius R, in the unit of the coordinates; or Nx\n"
     << "                     (e.g. 4x): N times the average spacing (CGAL::compute_average_\n"
     << "                     spacing, 6 neighbours; 4x gives about 45 neighbours on an even\n"
     << "                     sampling)\n"
     << "  --color Q          add red green blue (uchar) showing Q = mean|gaussian|k_min|k_max:\n"
     << "                     blue < 0 < red, white at 0, saturated beyond the 2nd/98th\n"
     << "                     percentiles; grey where invalid\n"
     << "  --ascii            ASCII PLY output (NaN written as nan)\n"
     << "  --require-normals  fail if INPUT has no normals instead of estimating them\n"
     << "  --threads N        use at most N threads (default: every core)\n"
     << "  --quiet            print errors only (no progress bar, warnings or summary)\n"
     << "  --help             print this help\n"
     << "\n"
     << "Exit status: 0 on success, 2 on an invalid argument or an unreadable, malformed or\n"
     << "unwritable file (nothing written), 130 if interrupted.\n";
}

// A finite number, the whole string (std::stod would accept "1.5abc").
bool parse_double(const std::string& s, double& value)
{
  if(s.empty() || std::isspace(static_cast<unsigned char>(s[0])))
    return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && errno == 0 && std::isfinite(value);
}

bool parse_positive_integer(const std::string& s, std::size_t& value)
{
  if(s.empty() || s.size() > 12)
    return false;
  for(char c : s)
    if(!std::isdigit(static_cast<unsigned char>(c)))
      return false;
  value = static_cast<std::size_t>(std::stoull(s));
  return value > 0;
}

void parse_radius(const std::string& text, Scale& scale)
{
  const bool multiple = !text.empty() && (text.back() == 'x' || text.back() == 'X');
  double value = 0;
  if(!parse_double(multiple ? text.substr(0, text.size() - 1) : text, value))
    throw Error(cat("--radius expects a positive length or a multiple of the average spacing "
                    "such as 4x, got ", in_quotes(text)));
  if(!(value > 0))
    throw Error(cat("--radius must be positive, got ", in_quotes(text)));
  scale.by_count = false;
  if(multiple)
    scale.spacing_multiple = value;
  else
    scale.radius = value;
}

Options parse_command_line(int argc, char** argv)
{
  Options o;
  std::vector<std::string> positional;
  o.method = find_method("aso");
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(arg.size() < 2 || arg[0] != '-')
    {
      positional.push_back(arg);
      continue;
    }
    std::string name = arg, value;
    bool inline_value = false;
    const std::size_t eq = arg.find('=');
    if(arg.compare(0, 2, "--") == 0 && eq != std::string::npos)
    {
      name = arg.substr(0, eq);
      value = arg.substr(eq + 1);
      inline_value = true;
    }
    auto take_value = [&]() -> std::string {
      if(inline_value)
        return value;
      if(i + 1 >= argc)
        throw Error(cat("option ", name, " needs a value (see --help)"));
      return argv[++i];
    };
    auto flag = [&](bool& b) {
      if(inline_value)
        throw Error(cat("option ", name, " takes no value"));
      b = true;
    };
    if(name == "--help" || name == "-h")
      flag(o.help);
    else if(name == "--method")
    {
      const std::string m = take_value();
      o.method = find_method(m);
      if(!o.method)
        throw Error(cat("--method: unknown method ", in_quotes(m), " (available: ", method_names(), ")"));
    }
    else if(name == "--radius")
    {
      parse_radius(take_value(), o.scale);
      o.radius_given = true;
    }
    else if(name == "--neighbors" || name == "--neighbours")
    {
      const std::string v = take_value();
      std::size_t k = 0;
      if(!parse_positive_integer(v, k) || k < 3)
        throw Error(cat(name, " must be an integer >= 3 (the fits need 3 points), got ", in_quotes(v)));
      o.scale.neighbors = k;
      o.neighbors_given = true;
    }
    else if(name == "--threads")
    {
      const std::string v = take_value();
      std::size_t n = 0;
      if(!parse_positive_integer(v, n) || n > 4096)
        throw Error(cat("--threads must be a positive integer, got ", in_quotes(v)));
      o.threads = static_cast<int>(n);
    }
    else if(name == "--color" || name == "--colour")
    {
      o.color = take_value();
      if(!color_quantities().count(o.color))
        throw Error(cat(name, ": unknown quantity ", in_quotes(o.color),
                        " (available: mean|gaussian|k_min|k_max)"));
    }
    else if(name == "--ascii")
      flag(o.ascii);
    else if(name == "--quiet")
      flag(o.quiet);
    else if(name == "--require-normals")
      flag(o.require_normals);
    else
      throw Error(cat("unknown option ", in_quotes(arg), " (see --help)"));
  }
  if(o.help)
    return o;
  if(positional.size() < 2)
    throw Error(cat("missing ", positional.empty() ? "INPUT and OUTPUT" : "OUTPUT", " (usage: ",
                    program, " INPUT OUTPUT [options]; see --help)"));
  if(positional.size() > 2)
    throw Error(cat("unexpected argument ", in_quotes(positional[2]), " (usage: ", program,
                    " INPUT OUTPUT [options])"));
  if(o.radius_given && o.neighbors_given)
    throw Error("give either --radius or --neighbors, not both");
  o.input = positional[0];
  o.output = positional[1];
  return o;
}

// ---------------------------------------------------------------------------------------
// Input. CGAL's readers accept some malformed files silently (the XYZ and OFF readers skip
// or truncate lines they cannot parse, the PLY reader ignores data beyond the declared
// counts), so the text formats are checked line by line first and PLY data is checked to
// end where the header says.

// CGAL's readers report details on std::cerr: keep them for the one-line error message.
class Capture_cerr
{
public:
  Capture_cerr() : m_old(std::cerr.rdbuf(m_text.rdbuf())) {}
  ~Capture_cerr() { std::cerr.rdbuf(m_old); }
  std::string first_line() const
  {
    std::string s = m_text.str();
    s = s.substr(0, s.find('\n'));
    return s;
  }

private:
  std::ostringstream m_text;
  std::streambuf* m_old;
};

std::string trim(const std::string& s)
{
  const std::size_t b = s.find_first_not_of(" \t\r");
  if(b == std::string::npos)
    return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> tokens(const std::string& line)
{
  std::vector<std::string> t;
  std::size_t b = 0;
  for(;;)
  {
    b = line.find_first_not_of(" \t\r", b);
    if(b == std::string::npos)
      return t;
    const std::size_t e = std::min(line.find_first_of(" \t\r", b), line.size());
    t.emplace_back(line, b, e - b);
    b = e;
  }
}

// A number as CGAL's text readers parse it (digits, sign, point, exponent: no nan or inf).
bool is_number(const std::string& token)
{
  if(token.find_first_not_of("0123456789+-.eE") != std::string::npos)
    return false;
  char* end = nullptr;
  std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size();
}

bool is_index(const std::string& token)
{
  return !token.empty() && token.find_first_not_of("0123456789") == std::string::npos &&
         token.size() < 19;
}

struct Text_check
{
  std::size_t points = 0;
  bool normals = false;
};

// .xyz/.pwn: optional point count alone on the first line, '#' comments, then 3 or 6 numbers
// per line, the same on every line.
Text_check check_xyz(const std::string& path)
{
  std::ifstream in(path);
  Text_check result;
  std::string line;
  std::size_t line_number = 0, declared = 0, columns = 0;
  bool has_count = false;
  while(std::getline(in, line))
  {
    ++line_number;
    const std::string t = trim(line);
    if(t.empty() || t[0] == '#')
      continue;
    const std::vector<std::string> w = tokens(t);
    if(line_number == 1 && w.size() == 1 && is_index(w[0]))
    {
      has_count = true;
      declared = static_cast<std::size_t>(std::stoull(w[0]));
      continue;
    }
    for(const std::string& token : w)
      if(!is_number(token))
        throw Error(cat(in_quotes(path), " line ", line_number, ": ", in_quotes(token), " is not a number"));
    if(w.size() != 3 && w.size() != 6)
      throw Error(cat(in_quotes(path), " line ", line_number, ": expected 3 (x y z) or 6 (x y z nx ny nz) values, found ",
                      w.size()));
    if(columns != 0 && w.size() != columns)
      throw Error(cat(in_quotes(path), " line ", line_number, ": ", w.size(), " values where the previous lines have ",
                      columns));
    columns = w.size();
    ++result.points;
  }
  if(in.bad())
    throw Error(cat("cannot read ", in_quotes(path), ": ", std::strerror(errno)));
  if(has_count && declared != result.points)
    throw Error(cat(in_quotes(path), ": its first line declares ", declared, " points but it has ",
                    result.points));
  result.normals = (columns == 6);
  return result;
}

// .off: "OFF" or "NOFF", then "V F E", V vertex lines of 3 numbers (6 with normals), F face
// lines of integers, and nothing else.
Text_check check_off(const std::string& path)
{
  std::ifstream in(path);
  Text_check result;
  std::string line, signature;
  std::size_t line_number = 0, declared_vertices = 0, declared_faces = 0, faces = 0, columns = 0;
  int stage = 0;  // 0 signature, 1 counts, 2 vertices, 3 faces
  while(std::getline(in, line))
  {
    ++line_number;
    const std::string t = trim(line);
    if(t.empty() || t[0] == '#')
      continue;
    const std::vector<std::string> w = tokens(t);
    auto fail = [&](const std::string& what) {
      throw Error(cat(in_quotes(path), " line ", line_number, ": ", what));
    };
    if(stage == 0)
    {
      if(w.size() != 1 || (w[0] != "OFF" && w[0] != "NOFF"))
        fail("expected the header OFF or NOFF (binary and coloured OFF are not supported)");
      signature = w[0];
      stage = 1;
    }
    else if(stage == 1)
    {
      if(w.size() != 3 || !is_index(w[0]) || !is_index(w[1]) || !is_index(w[2]))
        fail("expected the counts 'vertices faces edges'");
      declared_vertices = static_cast<std::size_t>(std::stoull(w[0]));
      declared_faces = static_cast<std::size_t>(std::stoull(w[1]));
      stage = declared_vertices > 0 ? 2 : 3;
    }
    else if(stage == 2)
    {
      for(const std::string& token : w)
        if(!is_number(token))
          fail(cat(in_quotes(token), " is not a number"));
      const std::size_t expected = signature == "NOFF" ? 6 : (columns ? columns : w.size());
      if((w.size() != 3 && w.size() != 6) || w.size() != expected)
        fail(cat("expected ", signature == "NOFF" ? "6 (x y z nx ny nz)" : "3 (x y z) or 6 (x y z nx ny nz)",
                 " values like the other vertices, found ", w.size(),
                 " (wrong vertex count in the header?)"));
      columns = w.size();
      if(++result.points == declared_vertices)
        stage = 3;
    }
    else
    {
      std::size_t corners = 0;
      if(!is_index(w[0]) || (corners = static_cast<std::size_t>(std::stoull(w[0]))) + 1 > w.size() ||
         faces >= declared_faces)
        fail(cat("unexpected line after the ", result.points, " vertices and ", faces,
                 " faces declared (wrong vertex or face count?)"));
      for(std::size_t c = 1; c <= corners; ++c)
        if(!is_index(w[c]) || std::stoull(w[c]) >= declared_vertices)
          fail(cat("face with an invalid vertex index ", in_quotes(w[c])));
      ++faces;
    }
  }
  if(in.bad())
    throw Error(cat("cannot read ", in_quotes(path), ": ", std::strerror(errno)));
  if(stage < 2)
    throw Error(cat(in_quotes(path), ": not an OFF file (missing header or counts)"));
  if(result.points != declared_vertices)
    throw Error(cat(in_quotes(path), ": the header declares ", declared_vertices,
                    " vertices but the file has ", result.points));
  if(faces != declared_faces)
    throw Error(cat(in_quotes(path), ": the header declares ", declared_faces,
                    " faces but the file has ", faces));
  result.normals = (columns == 6);
  return result;
}

// The PLY header: format and elements.
struct Ply_header
{
  struct Element
  {
    std::string name;
    std::size_t count = 0;
    std::vector<bool> list;  // per property: a list (count, then items) or a scalar
  };
  bool ascii = false;
  std::size_t vertices = 0;
  std::vector<Element> elements;
};

Ply_header check_ply_header(std::istream& in, const std::string& path)
{
  Ply_header h;
  std::string line;
  if(!std::getline(in, line) || trim(line) != "ply")
    throw Error(cat(in_quotes(path), ": not a PLY file (no 'ply' on its first line)"));
  bool format = false;
  while(std::getline(in, line))
  {
    const std::vector<std::string> w = tokens(line);
    if(w.empty())
      continue;
    if(w[0] == "end_header")
    {
      if(!format)
        throw Error(cat(in_quotes(path), ": PLY header without a format line"));
      return h;
    }
    if(w[0] == "format" && w.size() >= 2)
    {
      format = true;
      h.ascii = (w[1] == "ascii");
      if(!h.ascii && w[1] != "binary_little_endian" && w[1] != "binary_big_endian")
        throw Error(cat(in_quotes(path), ": unknown PLY format ", in_quotes(w[1])));
    }
    else if(w[0] == "element" && w.size() >= 3)
    {
      if(!is_index(w[2]))
        throw Error(cat(in_quotes(path), ": invalid PLY element count ", in_quotes(w[2])));
      h.elements.emplace_back();
      h.elements.back().name = w[1];
      h.elements.back().count = static_cast<std::size_t>(std::stoull(w[2]));
      if(w[1] == "vertex" || w[1] == "vertices")
        h.vertices = h.elements.back().count;
    }
    else if(w[0] == "property" && !h.elements.empty())
      h.elements.back().list.push_back(w.size() >= 2 && w[1] == "list");
  }
  throw Error(cat(in_quotes(path), ": truncated PLY header (no end_header)"));
}

// Why CGAL could not read an ASCII PLY file (its reader does not say): the first value that
// is not a number, or where the data ends.
std::string diagnose_ascii_ply(const std::string& path, const Ply_header& h)
{
  std::ifstream in(path);
  std::string line;
  std::size_t line_number = 0;
  while(std::getline(in, line))
  {
    ++line_number;
    if(trim(line) == "end_header")
      break;
  }
  std::vector<std::string> words;
  std::size_t next_word = 0;
  // the next value, or false at the end of the file
  auto next = [&](std::string& word) {
    while(next_word == words.size())
    {
      if(!std::getline(in, line))
        return false;
      ++line_number;
      words = tokens(line);
      next_word = 0;
    }
    word = words[next_word++];
    return true;
  };
  for(const Ply_header::Element& e : h.elements)
    for(std::size_t item = 0; item < e.count; ++item)
    {
      const std::string where = cat(e.name, " ", item + 1, " of the ", e.count, " declared in the header");
      for(bool list : e.list)
      {
        std::string word;
        if(!next(word))
          return cat("truncated: the file ends in ", where);
        if(!is_number(word))
          return cat("line ", line_number, ": ", in_quotes(word), " is not a number (", where, ")");
        if(list)
        {
          if(!is_index(word))
            return cat("line ", line_number, ": invalid list length ", in_quotes(word), " (", where, ")");
          for(std::size_t c = std::stoull(word); c > 0; --c)
          {
            if(!next(word))
              return cat("truncated: the file ends in ", where);
            if(!is_number(word))
              return cat("line ", line_number, ": ", in_quotes(word), " is not a number (", where, ")");
          }
        }
      }
    }
  return "malformed PLY data";
}

struct Input
{
  Point_set points;
  bool had_normals = false;
};

void read_input(const std::string& path, Input& input)
{
  struct stat st;
  if(::stat(path.c_str(), &st) != 0)
    throw Error(cat("cannot open input ", in_quotes(path), ": ", std::strerror(errno)));
  if(S_ISDIR(st.st_mode))
    throw Error(cat("cannot read input ", in_quotes(path), ": it is a directory"));
  {
    std::ifstream probe(path);
    if(!probe)
      throw Error(cat("cannot open input ", in_quotes(path), ": ", std::strerror(errno)));
  }
  const std::string ext = lower_extension(path);
  Point_set& ps = input.points;
  if(ext == ".xyz" || ext == ".pwn" || ext == ".off")
  {
    const Text_check check = ext == ".off" ? check_off(path) : check_xyz(path);
    std::ifstream in(path);
    bool ok = false;
    Capture_cerr capture;
    ok = ext == ".off" ? CGAL::IO::read_OFF(in, ps) : CGAL::IO::read_XYZ(in, ps);
    if(!ok)
      throw Error(cat("cannot read ", in_quotes(path), ": ", capture.first_line()));
    if(ps.size() != check.points)
      throw Error(cat("cannot read ", in_quotes(path), ": read ", ps.size(), " of its ", check.points,
                      " points"));
  }
  else if(ext == ".ply")
  {
    std::ifstream in(path, std::ios::binary);
    const Ply_header header = check_ply_header(in, path);
    in.clear();
    in.seekg(0);
    CGAL::IO::set_mode(in, CGAL::IO::BINARY);
    bool ok = false;
    {
      Capture_cerr capture;
      ok = CGAL::IO::read_PLY(in, ps);
    }
    if(!ok)
    {
      if(header.ascii)
        throw Error(cat(in_quotes(path), ": ", diagnose_ascii_ply(path, header)));
      // binary data can only be short: CGAL stopped in the first incomplete item
      if(ps.size() < header.vertices)
        throw Error(cat(in_quotes(path), ": truncated: the file ends in vertex ", ps.size() + 1,
                        " of the ", header.vertices, " declared in the header"));
      throw Error(cat(in_quotes(path), ": truncated: the file ends after the ", header.vertices,
                      " vertices, in a later element"));
    }
    if(ps.size() != header.vertices)
      throw Error(cat(in_quotes(path), ": the header declares ", header.vertices,
                      " vertices but ", ps.size(), " were read"));
    // data beyond the declared elements: the declared vertex count is wrong
    if(header.ascii)
      in >> std::ws;
    if(in.peek() != std::char_traits<char>::eof())
      throw Error(cat(in_quotes(path), ": more data than the ", header.vertices,
                      " vertices declared in the header (wrong vertex count?)"));
  }
  else
    throw Error(cat("unsupported input format ", in_quotes(ext.empty() ? path : ext), " for ",
                    in_quotes(path), " (expected .xyz, .pwn, .ply or .off)"));
  if(ps.empty())
    throw Error(cat(in_quotes(path), " contains no points"));
  input.had_normals = ps.has_normal_map();
}

// ---------------------------------------------------------------------------------------
// Normals

bool is_finite(const Point& p)
{
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}

std::vector<Point_set::Index> finite_points(const Point_set& ps)
{
  std::vector<Point_set::Index> indices;
  indices.reserve(ps.size());
  for(Point_set::Index i : ps)
    if(is_finite(ps.point(i)))
      indices.push_back(i);
  return indices;
}

// Unoriented normals by jet fitting, oriented along a minimum spanning tree (CGAL). Returns
// the number of points whose orientation could not be propagated.
std::size_t estimate_normals(Point_set& ps, std::size_t k)
{
  ps.add_normal_map();
  std::vector<Point_set::Index> indices = finite_points(ps);
  if(indices.size() <= k)
    return indices.size();  // too few points: normals stay zero (INVALID_NORMAL)
  const auto np = CGAL::parameters::point_map(ps.point_map()).normal_map(ps.normal_map());
  CGAL::jet_estimate_normals<CGAL::Parallel_tag>(indices, static_cast<unsigned int>(k), np);
  // mst_orient_normals partitions the range it is given: a copy of the indices keeps the
  // point set in input order
  const auto unoriented = CGAL::mst_orient_normals(indices, static_cast<unsigned int>(k), np);
  return static_cast<std::size_t>(std::distance(unoriented, indices.end()));
}

// ---------------------------------------------------------------------------------------
// Progress and interruption

volatile std::sig_atomic_t interrupted = 0;

extern "C" void on_interrupt(int)
{
  interrupted = 1;
  // a second Ctrl-C kills at once
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

class Progress_bar
{
public:
  explicit Progress_bar(bool enabled) : m_enabled(enabled), m_start(std::chrono::steady_clock::now()) {}

  bool operator()(double fraction)
  {
    if(m_enabled)
    {
      const int percent = static_cast<int>(100 * fraction);
      if(percent != m_last)
      {
        m_last = percent;
        const int width = 40, filled = percent * width / 100;
        const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
        std::fprintf(stderr, "\r[%s%s] %3d%% %6.1f s", std::string(filled, '#').c_str(),
                     std::string(width - filled, '.').c_str(), percent, seconds);
        std::fflush(stderr);
        m_drawn = true;
      }
    }
    return !interrupted;
  }

  void finish()
  {
    if(m_drawn)
      std::fputc('\n', stderr);
    m_drawn = false;
  }

private:
  bool m_enabled;
  std::chrono::steady_clock::time_point m_start;
  int m_last = -1;
  bool m_drawn = false;
};

// ---------------------------------------------------------------------------------------
// Output

// The output file is written under a temporary name in the same folder and renamed when
// complete, so that a failure or an interruption never leaves a partial OUTPUT.
class Temporary_output
{
public:
  explicit Temporary_output(const std::string& output) : m_output(output)
  {
    const std::size_t slash = output.find_last_of('/');
    const std::string folder = slash == std::string::npos ? "" : output.substr(0, slash + 1);
    const std::string name = slash == std::string::npos ? output : output.substr(slash + 1);
    if(name.empty())
      throw Error(cat("invalid output file name ", in_quotes(output)));
    std::string pattern = folder + "." + name + ".tmp-XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    const int fd = ::mkstemp(buffer.data());
    if(fd < 0)
      throw Error(cat("cannot write output ", in_quotes(output), ": ", std::strerror(errno)));
    m_path = buffer.data();
    // mkstemp creates the file readable by its owner only: give it the usual permissions
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    m_file = ::fdopen(fd, "wb");
    if(!m_file)
    {
      ::close(fd);
      discard();
      throw Error(cat("cannot write output ", in_quotes(output), ": ", std::strerror(errno)));
    }
    static char buffer_space[1 << 16];
    std::setvbuf(m_file, buffer_space, _IOFBF, sizeof(buffer_space));
  }

  ~Temporary_output() { discard(); }

  std::FILE* file() { return m_file; }

  void commit()
  {
    const bool written = !std::ferror(m_file);
    const bool closed = std::fclose(m_file) == 0;
    m_file = nullptr;
    if(!written || !closed)
      throw Error(cat("cannot write output ", in_quotes(m_output), ": ", std::strerror(errno)));
    if(std::rename(m_path.c_str(), m_output.c_str()) != 0)
      throw Error(cat("cannot write output ", in_quotes(m_output), ": ", std::strerror(errno)));
    m_path.clear();
  }

  void discard()
  {
    if(m_file)
      std::fclose(m_file);
    m_file = nullptr;
    if(!m_path.empty())
      std::remove(m_path.c_str());
    m_path.clear();
  }

private:
  std::string m_output, m_path;
  std::FILE* m_file = nullptr;
};

// Diverging colour map centred on 0 (Moreland's cool-warm end points): blue for negative,
// near-white at zero, red for positive, saturated beyond +-range.
std::array<unsigned char, 3> diverging_color(double v, double range)
{
  static const double blue[3] = {59, 76, 192}, white[3] = {221, 221, 221}, red[3] = {180, 4, 38};
  if(!std::isfinite(v))
    return {128, 128, 128};
  const double t = range > 0 ? std::max(-1.0, std::min(1.0, v / range)) : 0.0;
  const double* end = t < 0 ? blue : red;
  const double a = std::abs(t);
  std::array<unsigned char, 3> c;
  for(int i = 0; i < 3; ++i)
    c[i] = static_cast<unsigned char>(std::lround((1 - a) * white[i] + a * end[i]));
  return c;
}

// Value at fraction q of the sorted values (nearest rank).
double percentile(std::vector<double> values, double q)
{
  const std::size_t i = std::min(values.size() - 1, static_cast<std::size_t>(q * values.size()));
  std::nth_element(values.begin(), values.begin() + i, values.end());
  return values[i];
}

std::vector<double> finite_values(const Estimates& estimates, double Estimate::*field)
{
  std::vector<double> v;
  for(const Estimate& e : estimates)
    if(e.is_valid() && std::isfinite(e.*field))
      v.push_back(e.*field);
  return v;
}

// Symmetric colour range: the larger magnitude of the 2nd and 98th percentiles.
double robust_range(const std::vector<double>& values)
{
  if(values.empty())
    return 0;
  return std::max(std::abs(percentile(values, 0.02)), std::abs(percentile(values, 0.98)));
}

struct Record
{
  double value[16];
  std::int32_t neighbors;
  unsigned char valid;
};

const char* const field_names[16] = {"x", "y", "z", "nx", "ny", "nz", "k_min", "k_max", "mean",
                                     "gaussian", "dmin_x", "dmin_y", "dmin_z", "dmax_x", "dmax_y",
                                     "dmax_z"};

Record make_record(const Point& p, const Estimate& e)
{
  Record r;
  const double v[16] = {p.x(), p.y(), p.z(), e.normal.x(), e.normal.y(), e.normal.z(),
                        e.min_curvature, e.max_curvature, e.mean_curvature, e.gaussian_curvature,
                        e.min_direction.x(), e.min_direction.y(), e.min_direction.z(),
                        e.max_direction.x(), e.max_direction.y(), e.max_direction.z()};
  std::copy(v, v + 16, r.value);
  r.neighbors = static_cast<std::int32_t>(std::min<std::size_t>(e.neighbor_count, INT32_MAX));
  r.valid = e.is_valid() ? 1 : 0;
  return r;
}

void put_text_double(std::FILE* f, double v)
{
  if(std::isnan(v))
    std::fputs("nan", f);
  else
    std::fprintf(f, "%.17g", v);
}

// One row of text output (ASCII PLY, CSV): the 16 doubles, neighbors, valid and, if given,
// the colour, separated by `separator`.
void put_text_row(std::FILE* f, const Record& r, const unsigned char* color, char separator)
{
  for(int a = 0; a < 16; ++a)
  {
    put_text_double(f, r.value[a]);
    std::fputc(separator, f);
  }
  std::fprintf(f, "%d%c%d", int(r.neighbors), separator, int(r.valid));
  if(color)
    std::fprintf(f, "%c%d%c%d%c%d", separator, int(color[0]), separator, int(color[1]), separator,
                 int(color[2]));
  std::fputc('\n', f);
}

bool little_endian_host()
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

template <class T>
void put_binary(std::vector<char>& out, T v, bool swap)
{
  char bytes[sizeof(T)];
  std::memcpy(bytes, &v, sizeof(T));
  if(swap)
    std::reverse(bytes, bytes + sizeof(T));
  out.insert(out.end(), bytes, bytes + sizeof(T));
}

struct Output_description
{
  std::vector<std::string> comments;
  bool color = false;
};

void write_ply(std::FILE* f, bool ascii, const Point_set& ps, const Estimates& estimates,
               const std::vector<std::array<unsigned char, 3> >& colors, const Output_description& d)
{
  std::fprintf(f, "ply\nformat %s 1.0\n", ascii ? "ascii" : "binary_little_endian");
  for(const std::string& c : d.comments)
    std::fprintf(f, "comment %s\n", c.c_str());
  std::fprintf(f, "element vertex %zu\n", ps.size());
  for(const char* name : field_names)
    std::fprintf(f, "property double %s\n", name);
  std::fputs("property int neighbors\nproperty uchar valid\n", f);
  if(d.color)
    std::fputs("property uchar red\nproperty uchar green\nproperty uchar blue\n", f);
  std::fputs("end_header\n", f);

  const bool swap = !little_endian_host();
  std::vector<char> chunk;
  std::size_t i = 0;
  for(Point_set::Index idx : ps)
  {
    const Record r = make_record(ps.point(idx), estimates[i]);
    if(ascii)
      put_text_row(f, r, d.color ? colors[i].data() : nullptr, ' ');
    else
    {
      for(int a = 0; a < 16; ++a)
        put_binary(chunk, r.value[a], swap);
      put_binary(chunk, r.neighbors, swap);
      chunk.push_back(static_cast<char>(r.valid));
      if(d.color)
        for(int a = 0; a < 3; ++a)
          chunk.push_back(static_cast<char>(colors[i][a]));
      if(chunk.size() > (1u << 20))
      {
        std::fwrite(chunk.data(), 1, chunk.size(), f);
        chunk.clear();
      }
    }
    ++i;
  }
  if(!chunk.empty())
    std::fwrite(chunk.data(), 1, chunk.size(), f);
}

void write_csv(std::FILE* f, const Point_set& ps, const Estimates& estimates,
               const std::vector<std::array<unsigned char, 3> >& colors, const Output_description& d)
{
  for(const char* name : field_names)
    std::fprintf(f, "%s,", name);
  std::fputs("neighbors,valid", f);
  if(d.color)
    std::fputs(",red,green,blue", f);
  std::fputc('\n', f);
  std::size_t i = 0;
  for(Point_set::Index idx : ps)
  {
    put_text_row(f, make_record(ps.point(idx), estimates[i]), d.color ? colors[i].data() : nullptr, ',');
    ++i;
  }
}

// ---------------------------------------------------------------------------------------
// Summary

std::string min_median_max(const std::vector<double>& v, std::size_t valid)
{
  if(v.empty())
    return valid ? "n/a (not estimated by this method)" : "n/a (no valid estimate)";
  const auto mm = std::minmax_element(v.begin(), v.end());
  return cat("min ", *mm.first, "  median ", percentile(v, 0.5), "  max ", *mm.second);
}

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

std::string scale_description(const Scale& s)
{
  if(s.by_count)
    return cat(s.neighbors, " nearest neighbours per point (itself included)");
  if(s.spacing_multiple > 0)
    return cat("radius ", s.radius, " (", s.spacing_multiple, " x average spacing ", s.spacing, ")");
  return cat("radius ", s.radius);
}

int run(const Options& o)
{
  const auto start = std::chrono::steady_clock::now();
  const std::string out_ext = lower_extension(o.output);
  if(out_ext != ".ply" && out_ext != ".csv")
    throw Error(cat("unsupported output format ", in_quotes(out_ext.empty() ? o.output : out_ext),
                    " for ", in_quotes(o.output), " (expected .ply or .csv)"));

  std::unique_ptr<tbb::global_control> threads;
  if(o.threads > 0)
    threads.reset(new tbb::global_control(tbb::global_control::max_allowed_parallelism,
                                          static_cast<std::size_t>(o.threads)));

  // Created first: an unwritable OUTPUT fails before any long computation.
  Temporary_output output(o.output);
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  auto check_interrupted = [&]() {
    if(interrupted)
    {
      output.discard();
      std::fprintf(stderr, "%s: interrupted, nothing written\n", program);
      std::exit(130);
    }
  };
  auto warn = [&](const std::string& message) {
    if(!o.quiet)
      std::fprintf(stderr, "%s: warning: %s\n", program, message.c_str());
  };

  Input input;
  read_input(o.input, input);
  Point_set& ps = input.points;
  const double read_seconds = seconds_since(start);
  check_interrupted();

  const std::size_t normal_neighbors = 18;
  if(!input.had_normals)
  {
    if(o.require_normals)
      throw Error(cat(in_quotes(o.input), " has no normals (nx ny nz) and --require-normals was given"));
    warn(cat(in_quotes(o.input), " has no normals: estimating them (CGAL::jet_estimate_normals and "
             "CGAL::mst_orient_normals, ", normal_neighbors, " neighbours); a wrong orientation "
             "flips the sign of the curvatures"));
    const std::size_t usable = finite_points(ps).size();
    if(usable <= normal_neighbors)
      warn(cat("only ", usable, " points with finite coordinates: too few to estimate normals "
               "(more than ", normal_neighbors, " needed); every estimate will be invalid"));
    const std::size_t unoriented = estimate_normals(ps, normal_neighbors);
    if(unoriented > 0 && usable > normal_neighbors)
      warn(cat(unoriented, " points could not be oriented (isolated parts); their curvature "
               "signs may be wrong"));
  }
  const double normals_seconds = seconds_since(start) - read_seconds;
  check_interrupted();

  Scale scale = o.scale;
  const auto spacing_start = std::chrono::steady_clock::now();
  if(!scale.by_count && scale.spacing_multiple > 0)
  {
    const std::vector<Point_set::Index> indices = finite_points(ps);
    if(indices.size() < 7)
      throw Error(cat("--radius ", scale.spacing_multiple, "x: ", in_quotes(o.input),
                      " has fewer than 7 points, too few for an average spacing"));
    scale.spacing = CGAL::compute_average_spacing<CGAL::Parallel_tag>(
      indices, 6, CGAL::parameters::point_map(ps.point_map()));
    scale.radius = scale.spacing_multiple * scale.spacing;
    if(!(scale.radius > 0) || !std::isfinite(scale.radius))
      throw Error(cat("--radius ", scale.spacing_multiple, "x: the average spacing of ",
                      in_quotes(o.input), " is ", scale.spacing, " (coincident points?)"));
  }

  const double spacing_seconds = seconds_since(spacing_start);
  const auto estimation_start = std::chrono::steady_clock::now();
  Progress_bar progress(!o.quiet && ::isatty(STDERR_FILENO));
  progress(0.0);  // the bar shows at once: the first report comes after the first batch
  Estimates estimates;
  estimates = o.method->run(ps, scale, std::ref(progress));
  progress.finish();
  const double estimation_seconds = seconds_since(estimation_start);
  check_interrupted();

  Output_description description;
  description.comments.push_back(cat("point_set_curvatures method ", o.method->name, ", ",
                                     scale_description(scale)));
  description.comments.push_back(cat("input ", o.input));
  std::vector<std::array<unsigned char, 3> > colors;
  if(!o.color.empty())
  {
    const auto field = color_quantities().at(o.color);
    const std::vector<double> values = finite_values(estimates, field);
    if(values.empty())
      warn(cat("--color ", o.color, ": no valid value (not estimated by method ", o.method->name,
               "?); every point is grey"));
    const double range = robust_range(values);
    description.color = true;
    description.comments.push_back(
      cat("colors: ", o.color, ", blue -", range, " white 0 red +", range, ", grey invalid"));
    colors.reserve(estimates.size());
    for(const Estimate& e : estimates)
      colors.push_back(diverging_color(e.is_valid() ? e.*field : std::nan(""), range));
  }

  const auto write_start = std::chrono::steady_clock::now();
  if(out_ext == ".csv")
    write_csv(output.file(), ps, estimates, colors, description);
  else
    write_ply(output.file(), o.ascii, ps, estimates, colors, description);
  check_interrupted();
  output.commit();
  const double write_seconds = seconds_since(write_start);

  if(!o.quiet)
  {
    std::size_t valid = 0, neighbors = 0;
    std::map<std::string, std::size_t> invalid;
    for(const Estimate& e : estimates)
      if(e.is_valid())
      {
        ++valid;
        neighbors += e.neighbor_count;
      }
      else
        ++invalid[CGAL::to_string(e.status)];
    std::string why;
    for(const auto& s : invalid)
      why += cat(why.empty() ? "; " : ", ", s.second, " ", s.first);
    std::printf("%s: %s -> %s\n", program, o.input.c_str(), o.output.c_str());
    std::printf("  method      %s (%s)\n", o.method->name, o.method->description);
    std::printf("  scale       %s\n", scale_description(scale).c_str());
    std::printf("  points      %zu%s\n", ps.size(), input.had_normals ? "" : " (normals estimated)");
    std::printf("  valid       %zu (%.2f %%)%s\n", valid, 100.0 * valid / ps.size(), why.c_str());
    std::printf("  neighbours  %.2f on average (valid estimates)\n",
                valid ? double(neighbors) / valid : 0.0);
    std::printf("  time        %.3f s: read %.3f, normals %.3f, spacing %.3f, curvatures %.3f, "
                "write %.3f\n", seconds_since(start), read_seconds, normals_seconds, spacing_seconds,
                estimation_seconds, write_seconds);
    std::printf("  H (mean)    %s\n",
                min_median_max(finite_values(estimates, &Estimate::mean_curvature), valid).c_str());
    std::printf("  K (Gauss)   %s\n",
                min_median_max(finite_values(estimates, &Estimate::gaussian_curvature), valid).c_str());
  }
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const Options options = parse_command_line(argc, argv);
    if(options.help)
    {
      print_usage(std::cout);
      return 0;
    }
    return run(options);
  }
  catch(const Error& e)
  {
    std::fprintf(stderr, "%s: error: %s\n", program, e.what());
    return 2;
  }
  catch(const std::invalid_argument& e)
  {
    std::fprintf(stderr, "%s: error: %s\n", program, e.what());
    return 2;
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "%s: internal error: %s\n", program, e.what());
    return 1;
  }
}
