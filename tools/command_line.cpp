// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The command line of the point_set_curvatures tool (command_line.h).

#include "command_line.h"

#include "psc_io/read_point_cloud.h"
#include "run_summary.h"
#include "psc_io/write_point_cloud.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace psc_tool {

const std::map<std::string, int>& color_quantities()
{
  static const std::map<std::string, int> q = [] {
    std::map<std::string, int> m;
    for(int q = 0; q < summary_quantities::count(); ++q)
      m.emplace(summary_quantities::name[q], q);
    return m;
  }();
  return q;
}

std::size_t normal_neighbor_count(const Options& o)
{
  if(o.normal_neighbors > 0)
    return o.normal_neighbors;
  return CGAL::Point_set_curvatures::default_normal_neighbors(o.normal_fit);
}

std::size_t normal_automatic_largest(const Options& o)
{
  if(o.normal_fit != CGAL::Normal_fit::QUADRIC || o.scale.automatic_largest == 0)
    return 0;
  return std::max(o.scale.automatic_largest, normal_neighbor_count(o));
}

std::size_t normal_largest_count(const Options& o)
{
  return normal_automatic_largest(o) > 0 ? normal_automatic_largest(o) : normal_neighbor_count(o);
}

std::string normal_fit_description(const Options& o)
{
  if(normal_automatic_largest(o) > 0)
    return cat("a quadric fitted to the nearest neighbours, their count chosen per point from ",
               normal_neighbor_count(o), " to ", normal_automatic_largest(o));
  return cat(o.normal_fit == CGAL::Normal_fit::QUADRIC ? "a quadric fitted to the " : "the PCA plane of the ",
             normal_neighbor_count(o), " nearest neighbours");
}

namespace {

// The default neighbour count of the quadric normals.
std::size_t quadric_normal_neighbors()
{
  return CGAL::Point_set_curvatures::default_normal_neighbors(CGAL::Normal_fit::QUADRIC);
}

// "pca_plane 10; aso, apss, jet, wavejet 12; ...": each method's default --min-neighbors, by
// increasing count.
std::string least_neighbor_counts()
{
  std::map<std::size_t, std::string> by_count;
  for(const Method& m : methods())
    by_count[m.min_neighbors] += (by_count[m.min_neighbors].empty() ? "" : ", ") + std::string(m.name);
  std::string s;
  for(const auto& c : by_count)
    s += (s.empty() ? "" : "; ") + cat(c.second, " ", c.first);
  return s;
}

// `text` broken at spaces into lines of at most 90 characters: the first after `used`
// characters of its line, the others after `indent` spaces; no line break at the end.
std::string wrapped(const std::string& text, std::size_t used, std::size_t indent)
{
  std::string out, word;
  std::size_t column = used;
  std::istringstream words(text);
  while(words >> word)
  {
    const bool first = column == used && out.empty();
    if(!first && column + 1 + word.size() > 90)
    {
      out += "\n" + std::string(indent, ' ');
      column = indent;
    }
    else if(!first)
    {
      out += ' ';
      ++column;
    }
    out += word;
    column += word.size();
  }
  return out;
}

// "k_min|k_max|mean|gaussian": what --color can show, in the fields' order.
std::string color_choices()
{
  std::string s;
  for(const std::string_view name : summary_quantities::name)
    s += (s.empty() ? "" : "|") + std::string(name);
  return s;
}

}  // namespace

namespace {

// --neighbors auto: the ladder of counts from automatic_smallest to automatic_largest.
void use_automatic_scale(Estimation_settings& s)
{
  s.neighbors = automatic_smallest;
  s.automatic_largest = automatic_largest;
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

// "8G", "500M", "1.5g", "64k", "123456" (bytes): units are powers of 1024.
bool parse_memory_size(const std::string& text, double& bytes)
{
  if(text.empty())
    return false;
  double unit = 1;
  std::string number = text;
  const char last = static_cast<char>(std::toupper(static_cast<unsigned char>(text.back())));
  const std::string units = "KMGT";
  if(units.find(last) != std::string::npos)
  {
    unit = std::pow(1024.0, double(units.find(last) + 1));
    number.pop_back();
  }
  double v = 0;
  if(!parse_double(number, v) || !(v > 0) || !std::isfinite(v * unit))
    return false;
  bytes = v * unit;
  return true;
}

void parse_radius(const std::string& text, Estimation_settings& scale)
{
  const bool multiple = !text.empty() && (text.back() == 'x' || text.back() == 'X');
  double value = 0;
  if(!parse_double(multiple ? text.substr(0, text.size() - 1) : text, value))
    throw Error(
      cat("--radius expects a positive length or a multiple of the average spacing such as 4x, got ", in_quotes(text)));
  if(!(value > 0))
    throw Error(cat("--radius must be positive, got ", in_quotes(text)));
  scale.by_count = false;
  if(multiple)
    scale.spacing_multiple = value;
  else
    scale.radius = value;
}

// --orient: auto, mst, +z, -y, ..., or viewpoint:X,Y,Z.
CGAL::Normal_orientation parse_orientation(const std::string& text)
{
  if(text == "auto")
    return CGAL::Normal_orientation::automatic();
  if(text == "mst")
    return CGAL::Normal_orientation::minimum_spanning_tree();
  if(text == "scanner")  // +z, then each normal towards its pulse's origin (orient_towards_scanner())
    return CGAL::Normal_orientation::along_vector(0, 0, 1);
  if(text.size() == 2 && (text[0] == '+' || text[0] == '-') && text[1] >= 'x' && text[1] <= 'z')
  {
    double v[3] = {0, 0, 0};
    v[text[1] - 'x'] = text[0] == '+' ? 1 : -1;
    return CGAL::Normal_orientation::along_vector(v[0], v[1], v[2]);
  }
  const std::string prefix = "viewpoint:";
  if(text.compare(0, prefix.size(), prefix) == 0)
  {
    std::string rest = text.substr(prefix.size());
    double v[3];
    for(int a = 0; a < 3; ++a)
    {
      const std::size_t comma = a < 2 ? rest.find(',') : std::string::npos;
      if((a < 2 && comma == std::string::npos) || !parse_double(rest.substr(0, comma), v[a]))
        throw Error(cat("--orient ", in_quotes(text), ": expected viewpoint:X,Y,Z with three numbers"));
      rest = a < 2 ? rest.substr(comma + 1) : "";
    }
    return CGAL::Normal_orientation::towards_point(v[0], v[1], v[2]);
  }
  throw Error(cat("--orient: unknown orientation ", in_quotes(text),
                  " (auto, mst, +z, -z, +x, -x, +y, -y, viewpoint:X,Y,Z or scanner)"));
}

// One option of the command line, declared once: --help prints the table, the parser reads it.
struct Option_spec
{
  // the --help heading this option starts ("the estimator"), or null (the previous option's)
  const char* heading;
  // its spellings, the first in --help
  std::vector<std::string> names;
  // the name of its value in --help; null: a flag, which takes none
  const char* value;
  // its text in --help, from column 21 (lines joined by help_lines())
  std::string help;
  // what it does to the options, given the spelling used and its value ("" for a flag); null:
  // a line of --help only (a value of the option above it, such as --neighbors auto)
  void (*apply)(Options& o, const std::string& name, const std::string& value);
};

// The lines of an option's text in --help, each after the first indented to column 21.
std::string help_lines(std::initializer_list<std::string> lines)
{
  std::string text;
  for(const std::string& line : lines)
    text += (text.empty() ? "" : "\n" + std::string(21, ' ')) + line;
  return text;
}

const std::vector<Option_spec>& option_table()
{
  namespace PSC = CGAL::Point_set_curvatures;
  typedef const std::string& S;
  // (a table laid out by hand: one option a row, its help lines as --help prints them)
  // clang-format off
  static const std::vector<Option_spec> table = {
    {"the estimator", {"--method"}, "M", cat("estimator: ", method_names(), " (default aso)"),
     [](Options& o, S, S v) {
       o.method = find_method(v);
       if(!o.method)
         throw Error(cat("--method: unknown method ", in_quotes(v), " (available: ", method_names(), ")"));
     }},
    {nullptr, {"--variant"}, "V",
     help_lines({"aso: robust (default: kernel (1-d^2/r^2)^3, tangent Voronoi area",
                 "weights, neighbours' normals oriented by their majority, a fit of",
                 "the normal field blended in at borders) or paper (the estimator",
                 "of Lejemble et al. 2021 exactly)"}),
     [](Options& o, S, S v) {
       const auto& names = PSC::aso_variant_names;
       const auto found = std::find(std::begin(names), std::end(names), v);
       if(found == std::end(names))
         throw Error(cat("--variant: unknown variant ", in_quotes(v), " (robust or paper)"));
       o.scale.variant = CGAL::Aso_variant(found - std::begin(names));
     }},

    {"the neighbourhoods (the scale)", {"--neighbors", "--neighbours"}, "K",
     help_lines({"neighbourhoods by count: each point's radius is the distance to its",
                 "K-th nearest neighbour, itself counted (default: auto for the",
                 cat("aso's robust variant, else ", PSC::front_end_defaults::neighbor_count, ")")}),
     [](Options& o, S name, S v) {
       std::size_t k = 0;
       if(v == "auto")
         use_automatic_scale(o.scale);
       else if(!parse_positive_integer(v, k) || k < 3)
         throw Error(cat(name, " must be an integer >= 3 (the fits need 3 points) or auto, got ", in_quotes(v)));
       else
       {
         o.scale.neighbors = k;
         o.scale.automatic_largest = 0;
       }
       o.neighbors_given = true;
     }},
    {nullptr, {"--neighbors"}, "auto",
     help_lines({cat("aso: each point's count chosen among ", automatic_smallest, ", ", 2 * automatic_smallest, ", ..., ",
                     automatic_largest, " by the noise"),
                 "its fits measure: 40 on clean surfaces, more on noisy scans (the",
                 "neighbors field gives the count); --neighbors 40 is faster: 1.7x on",
                 "clean surfaces, 7x on a real airborne tile, where most counts grow"}),
     nullptr},
    {nullptr, {"--radius"}, "R",
     help_lines({"neighbourhoods of radius R, in the unit of the coordinates; or Nx",
                 "(e.g. 3.5x): N times the average spacing (CGAL::compute_average_",
                 "spacing, 6 neighbours); on even samplings 3x gives about 27",
                 "neighbours, 3.5x about 37, 4x about 47"}),
     [](Options& o, S, S v) {
       parse_radius(v, o.scale);
       o.radius_given = true;
     }},
    {nullptr, {"--min-neighbors", "--min-neighbours"}, "M",
     help_lines({"estimates with fewer than M neighbours are invalid",
                 "(too_few_neighbors); default: the method's measured minimum",
                 cat("(", least_neighbor_counts(), ")")}),
     [](Options& o, S name, S v) {
       std::size_t m = 0;
       if(!parse_positive_integer(v, m))
         throw Error(cat(name, " must be a positive integer, got ", in_quotes(v)));
       o.scale.min_neighbors = m;
     }},

    {"the input", {"--columns"}, "LIST",
     help_lines({"names of the values of a text line, comma-separated: x y z, nx ny nz",
                 "(or normal_x ...), anything else skipped (e.g. x,y,z,r,g,b or", "x,y,z,_,_,_,nx,ny,nz)"}),
     [](Options& o, S, S v) { o.columns = parse_columns(v); }},
    {nullptr, {"--allow-truncated"}, nullptr,
     help_lines({"read a LAS file whose last point records are missing up to its",
                 "last complete record, with a warning (default: refused)"}),
     [](Options& o, S, S) { o.allow_truncated = true; }},
    {nullptr, {"--require-normals"}, nullptr, "fail if INPUT has no normals instead of estimating them",
     [](Options& o, S, S) { o.require_normals = true; }},

    {"the normals, where INPUT has none", {"--orient"}, "O",
     help_lines({"orientation of estimated normals: auto (default: LAS files with",
                 "pulse directions, scanner; other LAS files, mst with +z on its open",
                 "parts if the cloud is 2.5-D (60% of the normals within 60 degrees of",
                 "the vertical); other files, mst), mst (propagated along a minimum spanning",
                 "tree, each connected part outward if closed, up if open), +z, -z,",
                 "+x, -x, +y, -y (airborne scans: +z), viewpoint:X,Y,Z (towards the",
                 "scanner at X,Y,Z), or scanner (LAS point formats 4, 5, 9, 10:",
                 "towards the origin of each point's pulse, its wave packet's x(t)",
                 "y(t) z(t)). The summary says which was used and why"}),
     [](Options& o, S, S v) {
       o.orientation_text = v;
       o.orientation = parse_orientation(v);
       o.orient_scanner = v == "scanner";
     }},
    {nullptr, {"--normal-fit"}, "F",
     help_lines({"fit of the normal estimation: quadric (default: a weighted quadric,",
                 "smooth from point to point, which the ASO needs) or plane (PCA)"}),
     [](Options& o, S, S v) {
       if(v != "quadric" && v != "plane")
         throw Error(cat("--normal-fit: unknown fit ", in_quotes(v), " (quadric or plane)"));
       o.normal_fit = v == "plane" ? CGAL::Normal_fit::PLANE : CGAL::Normal_fit::QUADRIC;
     }},
    {nullptr, {"--normal-neighbors", "--normal-neighbours"}, "K",
     help_lines({cat("neighbours of the normal estimation (default ", quadric_normal_neighbors(), ", the least with"),
                 cat("the automatic scale; plane ", PSC::default_normal_neighbors(CGAL::Normal_fit::PLANE), ")")}),
     [](Options& o, S name, S v) {
       if(!parse_positive_integer(v, o.normal_neighbors) || o.normal_neighbors < 3)
         throw Error(cat(name, " must be an integer >= 3, got ", in_quotes(v)));
     }},
    {nullptr, {"--position-blend"}, "W",
     help_lines({"aso: weight in [0, 1] of a quadric fitted to the positions alone,",
                 "blended with the ASO's tensor (default 0.5 for the robust variant",
                 "when the normals are estimated: within 1.35x of the error with",
                 "exact normals on simulated scans; otherwise 0)"}),
     [](Options& o, S, S v) {
       if(!parse_double(v, o.position_blend) || !(o.position_blend >= 0 && o.position_blend <= 1))
         throw Error(cat("--position-blend must be a number in [0, 1], got ", in_quotes(v)));
     }},

    {"the output", {"--fields"}, "LIST",
     wrapped(cat("estimator fields to write, comma-separated (x y z always; default: all, in this order): ",
                 selectable_fields()),
             21, 21),
     [](Options& o, S, S v) { o.fields = parse_fields(v); }},
    {nullptr, {"--float"}, nullptr, "write the estimator fields as float32 (x y z stay double)",
     [](Options& o, S, S) { o.float32 = true; }},
    {nullptr, {"--ascii"}, nullptr, "ASCII PLY output (NaN written as nan)",
     [](Options& o, S, S) { o.ascii = true; }},
    {nullptr, {"--ply-names"}, "N",
     help_lines({"names of the PLY properties: plain (default: mean, k_min, ...) or",
                 "scalar (scalar_mean, scalar_k_min, ...: every property but x y z,",
                 "nx ny nz and red green blue, input attributes too). CloudCompare",
                 "loads a property scalar_NAME as the scalar field NAME and leaves",
                 "out mean, k_min, ...: use scalar for CloudCompare"}),
     [](Options& o, S, S v) {
       if(v != "plain" && v != "scalar")
         throw Error(cat("--ply-names: unknown naming ", in_quotes(v),
                         " (plain, or scalar for CloudCompare's scalar_NAME)"));
       o.ply_scalar_names = v == "scalar";
     }},
    {nullptr, {"--color", "--colour"}, "Q",
     help_lines({cat("add red green blue (uchar) showing Q = ", color_choices(), ":"),
                 "blue < 0 < red, white at 0, saturated beyond the 2nd/98th", "percentiles; grey where invalid"}),
     [](Options& o, S name, S v) {
       o.color = v;
       if(!color_quantities().count(o.color))
         throw Error(cat(name, ": unknown quantity ", in_quotes(o.color), " (available: ", color_choices(), ")"));
     }},
    {nullptr, {"--drop-attributes"}, nullptr,
     help_lines({"do not carry the input's other values to the output (a .las",
                 "output keeps a LAS input's standard fields, drops its extra bytes)"}),
     [](Options& o, S, S) { o.drop_attributes = true; }},

    {"large files, the run", {"--memory-limit"}, "M",
     help_lines({"memory for the points, in bytes or with a unit: 500M, 8G (default:",
                 "a quarter of the machine's RAM). A larger input is estimated in",
                 "spatial tiles, each read again from INPUT with a halo around it,",
                 "the rows written in input order: the same output, bitwise, in",
                 "bounded memory (--radius as a length; without normals, they are",
                 "estimated in tiles first; a spanning tree (mst, auto but on LAS",
                 "files with pulses) orients them over the whole cloud in memory,",
                 "about 450 bytes a point; not --method vcm,",
                 "which needs every point; the automatic scale's halos",
                 cat("reach ", automatic_largest, " neighbours). A limit that makes more than 500 tiles, or"),
                 "above the machine's RAM, is warned of"}),
     [](Options& o, S, S v) {
       if(!parse_memory_size(v, o.memory_limit))
         throw Error(cat("--memory-limit expects a positive size in bytes or with a unit (500M, 8G), got ",
                         in_quotes(v)));
     }},
    {nullptr, {"--threads"}, "N", "use at most N threads (default: every core)",
     [](Options& o, S, S v) {
       std::size_t n = 0;
       if(!parse_positive_integer(v, n) || n > 4096)
         throw Error(cat("--threads must be a positive integer, got ", in_quotes(v)));
       o.threads = static_cast<int>(n);
     }},
    {nullptr, {"--quiet"}, nullptr,
     help_lines({"print errors only (no progress bar, warnings, notes or summary;",
                 "the progress bar, with the elapsed time and an ETA, is drawn", "only when stderr is a terminal)"}),
     [](Options& o, S, S) { o.quiet = true; }},
    {nullptr, {"--help", "-h"}, nullptr, "print this help", [](Options& o, S, S) { o.help = true; }},
  };
  // clang-format on
  return table;
}

}  // namespace

void print_usage(std::ostream& os)
{
  os << "usage: " << program << " INPUT OUTPUT [options]\n"
     << "\n"
     << "Estimates curvatures at every point of a point cloud.\n"
     << "  INPUT   .xyz, .pwn, .txt, .csv or .asc (CloudCompare's ASCII export): one point per\n"
     << "          line, values separated by spaces or commas: x y z, or x y z nx ny nz, or a\n"
     << "          header line naming the columns, or --columns; .ply (ASCII or binary, normals\n"
     << "          nx ny nz or normal_x normal_y normal_z), .off, .las (LAS 1.0-1.4 uncompressed,\n"
     << "          point formats 0-10; .laz: decompress first). Without normals, they are\n"
     << "          estimated (a quadric fitted to the " << quadric_normal_neighbors() << " nearest neighbours, or "
     << quadric_normal_neighbors() << " to " << automatic_largest << " with the\n"
     << "          automatic scale; see --normal-fit and --orient) with a warning.\n"
     << "  OUTPUT  .ply (binary unless --ascii) or .csv (with a header line): every input point\n"
     << "          in input order with x y z and the fields of --fields: the corrected normal,\n"
     << "          the curvatures, the principal directions, normal_coherence (a quality value\n"
     << "          in [0, 1]: 1 where the neighbours' normals agree, low in foliage; aso and\n"
     << "          apss), with the automatic scale mean_error (the standard error of mean at the\n"
     << "          chosen scale) (doubles; NaN where the estimate is invalid or the method does\n"
     << "          not provide the quantity), neighbors (int) and valid (0 or 1); then the\n"
     << "          input's other values in their own types (PLY properties, named text columns,\n"
     << "          LAS fields such as intensity, classification, gps_time, red green blue, and\n"
     << "          the extra bytes an extra-bytes VLR describes), renamed input_NAME where NAME\n"
     << "          is one of the tool's fields; 16-bit red green blue are written to PLY as 8\n"
     << "          bits, as viewers read them (the high byte; the value where none in the file\n"
     << "          exceeds 255).\n"
     << "          Or .las: LAS 1.4 with the estimates as extra-bytes fields (double, float\n"
     << "          with --float; no_data NaN where invalid), from a LAS input in its point\n"
     << "          format with its fields, scale, offset, VLRs, extended VLRs and CRS kept;\n"
     << "          otherwise format 6, offset at the floor of the minimum, scale 0.001 (finer\n"
     << "          for extents below 1000). A LAS input whose CRS is geographic, or whose x y\n"
     << "          look like degrees, gets a warning: reproject it to metres first.\n";
  // the options, from the table: the flag and its value's name, then the text from column 21
  for(const Option_spec& option : option_table())
  {
    if(option.heading)
      os << "\noptions: " << option.heading << "\n";
    const std::string left = option.names.front() + (option.value ? cat(" ", option.value) : std::string());
    os << "  " << left << (left.size() < 19 ? std::string(19 - left.size(), ' ') : std::string("  ")) << option.help
       << "\n";
  }
  os << "\n"
     << "Exit status: 0 on success; 2 on an invalid argument or an unreadable, malformed or\n"
     << "unwritable file (nothing written; an OUTPUT that is a directory or in a missing or\n"
     << "read-only folder, and a disk too full for the output, whose size is reserved once INPUT\n"
     << "is read, fail before the estimation); 3 when no point got a valid estimate (OUTPUT is\n"
     << "written, every row invalid; stderr says why, such as too few neighbours, and what to\n"
     << "try, such as a radius); 130 if interrupted by Ctrl-C (SIGINT) and 143 by SIGTERM, in\n"
     << "any phase (nothing written); 1 on an internal error. A run killed while writing\n"
     << "leaves a hidden .OUTPUT.tmp-PID-XXXXXX, which the next run writing OUTPUT removes\n"
     << "(with a note).\n";
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
    const auto& table = option_table();
    const auto option = std::find_if(table.begin(), table.end(), [&name](const Option_spec& s) {
      return s.apply && std::find(s.names.begin(), s.names.end(), name) != s.names.end();
    });
    if(option == table.end())
      throw Error(cat("unknown option ", in_quotes(arg), " (see --help)"));
    if(!option->value)
    {
      if(inline_value)
        throw Error(cat("option ", name, " takes no value"));
    }
    else if(!inline_value)
    {
      if(i + 1 >= argc)
        throw Error(cat("option ", name, " needs a value (see --help)"));
      value = argv[++i];
    }
    option->apply(o, name, value);
  }
  if(o.help)
    return o;
  if(positional.size() < 2)
    throw Error(cat("missing ", positional.empty() ? "INPUT and OUTPUT" : "OUTPUT", " (usage: ", program,
                    " INPUT OUTPUT [options]; see --help)"));
  if(positional.size() > 2)
    throw Error(
      cat("unexpected argument ", in_quotes(positional[2]), " (usage: ", program, " INPUT OUTPUT [options])"));
  if(o.radius_given && o.neighbors_given)
    throw Error("give either --radius or --neighbors, not both");
  // The default scale (the library's front_end_defaults): automatic for the ASO's robust
  // variant, else 40 (Estimation_settings::neighbors).
  if(!o.radius_given && !o.neighbors_given &&
     CGAL::Point_set_curvatures::front_end_defaults::automatic_scale(*o.method, o.scale.variant))
    use_automatic_scale(o.scale);
  if(o.scale.automatic_largest > 0 && !o.method->supports_automatic_scale)
    throw Error(cat("--neighbors auto chooses the scale of --method aso only; give --method ", o.method->name,
                    " a count (--neighbors K)"));
  if(o.scale.automatic_largest == 0)
    for_each_tool_field([&o](const CGAL::Point_set_curvatures::Field_description& f) {
      if(f.automatic_scale_only && std::find(o.fields.begin(), o.fields.end(), f.name) != o.fields.end())
        throw Error(
          cat("--fields: ", f.name, " comes with the automatic scale only: add --neighbors auto, or leave it out"));
    });
  if(o.normal_fit == CGAL::Normal_fit::QUADRIC && o.normal_neighbors != 0 && o.normal_neighbors < 6)
    throw Error(cat("--normal-neighbors ", o.normal_neighbors,
                    " is below the 6 points a quadric needs: use --normal-neighbors 6 or more, or --normal-fit plane"));
  const std::size_t least = o.scale.min_neighbors ? o.scale.min_neighbors : o.method->min_neighbors;
  if(o.scale.by_count && o.scale.neighbors < least)
    throw Error(cat("--neighbors ", o.scale.neighbors, " is below the ", least, " neighbours of a valid ",
                    o.method->name, " estimate",
                    o.scale.min_neighbors ? " (--min-neighbors)" : " (measured minimum, see the manual)",
                    ": every estimate would be invalid; use --neighbors ", least,
                    " or more, or lower the threshold with --min-neighbors"));
  o.input = positional[0];
  o.output = positional[1];
  if(o.ply_scalar_names && lower_extension(o.output) != ".ply")
    throw Error(cat("--ply-names scalar names the properties of a .ply output; ", in_quotes(o.output),
                    " is not one: write OUTPUT.ply, or drop --ply-names"));
  return o;
}

}  // namespace psc_tool
