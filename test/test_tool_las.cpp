// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's LAS input and output (issues 12 and 28): point formats 0-10 and their fields, extra
// bytes in their types, LAS 1.4 output read by an independent reader, geographic and truncated files,
// input attributes carried to the output, --fields, --float.

#include "las_test_reader.h"
#include "test_tool_support.h"

using namespace psc_tool_test;

// ---------------------------------------------------------------------------------------
// LAS input, attributes carried to the output, --fields, --float (issue 12)

TEST_CASE("tool: LAS 1.0-1.4 point formats 0-10 with their fields as attributes, refused and suspicious LAS files")
{
  // a sphere of radius 2 in LiDAR coordinates (offset 1e6, 2e6, 100; millimetre scale)
  const double offset[3] = {1e6, 2e6, 100};
  std::vector<Oriented_point> pts;
  for(const Oriented_point& p : sphere(3000, 2.0))
    pts.emplace_back(Point(p.first.x() + 1e6 + 3, p.first.y() + 2e6 + 4, p.first.z() + 105), p.second);
  const std::string viewpoint = " --orient viewpoint:1000003,2000004,105";  // normals inwards: H = -1/2
  std::string reference_curvatures;
  // each format in the first version that has it, and formats 0 and 1 in LAS 1.0 and 1.1 too
  // (the same 227-byte header as 1.2 for what the reader uses)
  std::vector<std::pair<int, int> > versions;
  for(int format = 0; format <= 10; ++format)
    versions.emplace_back(format, format >= 6 ? 4 : format >= 4 ? 3 : 2);
  for(int minor : {0, 1})
    for(int format : {0, 1})
      versions.emplace_back(format, minor);
  for(const auto& version : versions)
  {
    const int format = version.first, minor = version.second;
    INFO("point format " << format << ", LAS 1." << minor);
    const std::string las =
                        file("f" + std::to_string(format) + (minor < 2 ? "_1" + std::to_string(minor) : "") + ".las"),
                      out = file("f.ply");
    const auto quantised = write_las(las, pts, format, minor, 0.001, offset, format == 8 ? 5 : 0);
    const Run r = run_tool(q(las) + " " + q(out) + " --radius 0.5" + viewpoint);
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(r.out.find("valid       3000 (100.00 %)") != std::string::npos);
    Point_set ps;
    REQUIRE(CGAL::IO::read_PLY(out, ps));
    REQUIRE(ps.size() == pts.size());
    const auto mean = property<double>(ps, "mean");
    const auto intensity = property<std::uint16_t>(ps, "intensity");
    const auto classification = property<std::uint8_t>(ps, "classification");
    const auto returns = property<std::uint8_t>(ps, "number_of_returns");
    const auto angle = property<float>(ps, "scan_angle");
    std::size_t i = 0, wrong = 0;
    double worst_h = 0;
    std::ostringstream curvatures;
    curvatures.precision(17);
    for(Point_set::Index p : ps)
    {
      const Point& x = ps.point(p);
      wrong += (x.x() != quantised[i][0] || x.y() != quantised[i][1] || x.z() != quantised[i][2]) ? 1 : 0;
      wrong += intensity[p] != las_intensity(i) || classification[p] != las_classification(i) || returns[p] != 2 ||
               std::abs(angle[p] + 12) > 1e-4;
      worst_h = std::max(worst_h, std::abs(mean[p] + 0.5));
      curvatures << mean[p] << " ";
      ++i;
    }
    CHECK(wrong == 0);
    CHECK(worst_h < 0.05);
    // the same positions whatever the format: the same curvatures
    if(reference_curvatures.empty())  // format 0, LAS 1.2: every other row is compared with it
      reference_curvatures = curvatures.str();
    CHECK(curvatures.str() == reference_curvatures);
    const bool gps = format != 0 && format != 2, rgb = format == 2 || format == 3 || format == 5 || format >= 7;
    CHECK(ps.property_map<double>("gps_time").second == gps);
    CHECK(ps.property_map<std::uint8_t>("red").second == (rgb && format != 9));  // (8 bits in PLY)
    CHECK(ps.property_map<std::uint8_t>("overlap").second == (format >= 6));
    CHECK(ps.property_map<std::uint16_t>("nir").second == (format == 8 || format == 10));
    if(gps)
    {
      const auto t = property<double>(ps, "gps_time");
      std::size_t k = 0, bad = 0;
      for(Point_set::Index p : ps)
        bad += t[p] != las_gps_time(k++);
      CHECK(bad == 0);
    }
    if(format == 3 || format == 8)
    {
      const auto red = property<std::uint8_t>(ps, "red");
      std::size_t k = 0, bad = 0;
      for(Point_set::Index p : ps)
        bad += red[p] != las_red(k++) >> 8;
      CHECK(bad == 0);
    }
  }

  // Refused, exit 2, one line, no output: .laz, a compressed format byte, a truncated file,
  // a record length below the format's, no signature, a format not valid in the version.
  const std::string good = read_text(file("f3.las"));
  auto variant = [&](const std::string& name, std::size_t at, const std::string& bytes, std::size_t keep = 0) {
    std::string s = good;
    if(keep)
      s.resize(keep);
    s.replace(at, bytes.size(), bytes);
    write_text(file(name), s);
  };
  write_text(file("c.laz"), good);
  variant("compressed.las", 104, std::string(1, char(0x83)));
  variant("truncated.las", 0, "L", good.size() - 10);
  variant("short_record.las", 105, std::string("\x10\x00", 2));
  variant("signature.las", 0, "LASX");
  variant("format7_in_12.las", 104, std::string(1, char(7)));
  const std::pair<const char*, const char*> refused[] = {
    {"c.laz", "decompress it first"},
    {"compressed.las", "compressed LAS (LAZ) data"},
    {"truncated.las", "truncated: the header declares 3000 points"},
    {"short_record.las", "point record length 16 is smaller than the 34 bytes of point format 3"},
    {"signature.las", "no 'LASF' signature"},
    {"format7_in_12.las", "point data record format 7 is not valid in LAS 1.2"}};
  for(const auto& c : refused)
  {
    INFO(c.first);
    fs::remove(file("refused.ply"));
    const Run r = run_tool(q(file(c.first)) + " " + q(file("refused.ply")));
    CHECK(r.status == 2);
    CHECK(r.err.find(c.second) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(!fs::exists(file("refused.ply")));
  }
  // --orient scanner: each normal towards the origin of its pulse (the wave packets' x(t) y(t)
  // z(t) of formats 4, 5, 9, 10), here the sphere's centre: the same normals, so the same
  // output, as --orient viewpoint at the centre; in memory and in tiles
  const double centre[3] = {1e6 + 3, 2e6 + 4, 105};
  for(int format : {4, 9, 10})
  {
    INFO("point format " << format);
    const std::string las = file("w" + std::to_string(format) + ".las");
    write_las(las, pts, format, format == 4 ? 3 : 4, 0.001, offset, 0, centre);
    const Run scanner = run_tool(q(las) + " " + q(file("scanner.ply")) + " --radius 0.5 --orient scanner");
    const Run view = run_tool(q(las) + " " + q(file("view.ply")) + " --radius 0.5" + viewpoint);
    REQUIRE(scanner.status == 0);
    REQUIRE(view.status == 0);
    CHECK(scanner.out.find("valid       3000 (100.00 %)") != std::string::npos);
    const std::string a = read_text(file("scanner.ply")), b = read_text(file("view.ply"));
    CHECK(a.substr(a.find("end_header")) == b.substr(b.find("end_header")));
    CHECK(a.find("property float wave_x_t\nproperty float wave_y_t\nproperty float wave_z_t\n") != std::string::npos);
    const Run tiled =
      run_tool(q(las) + " " + q(file("scanner_tiled.ply")) + " --radius 0.5 --orient scanner --memory-limit 1200K");
    REQUIRE(tiled.status == 0);
    CHECK(tiled.out.find("  tiles") != std::string::npos);
    CHECK(read_text(file("scanner_tiled.ply")) == a);
  }
  {
    // pulses without a direction (x(t) y(t) z(t) zero: the last 12 bytes of the first 10
    // records) keep +z, said alike in memory and in tiles (one estimation step for both)
    std::string las = read_text(file("w4.las"));
    std::uint32_t first = 0;
    std::uint16_t length = 0;
    std::memcpy(&first, &las[96], 4);
    std::memcpy(&length, &las[105], 2);
    for(std::size_t i = 0; i < 10; ++i)
      std::fill_n(las.begin() + first + (i + 1) * length - 12, 12, '\0');
    write_text(file("undirected.las"), las);
    const std::string said = "warning: --orient scanner: 10 points have no pulse direction and keep normals "
                             "oriented to +z";
    const Run whole = run_tool(q(file("undirected.las")) + " " + q(file("u.ply")) + " --radius 0.5 --orient scanner");
    const Run tiled = run_tool(q(file("undirected.las")) + " " + q(file("u_tiled.ply")) +
                               " --radius 0.5 --orient scanner --memory-limit 1200K");
    REQUIRE(whole.status == 0);
    REQUIRE(tiled.status == 0);
    CHECK(whole.err.find(said) != std::string::npos);
    CHECK(tiled.err.find(said) != std::string::npos);
    CHECK(tiled.out.find("  tiles") != std::string::npos);
    CHECK(read_text(file("u_tiled.ply")) == read_text(file("u.ply")));
    // a file with normals and no pulses: --orient scanner has nothing to turn, in memory and
    // in tiles (it indexed the missing pulse attributes)
    write_xyz(file("oriented.xyz"), sphere(3000, 1.0));
    for(const char* limit : {"", " --memory-limit 400K"})
    {
      INFO("oriented.xyz --orient scanner" << limit);
      const Run r =
        run_tool(q(file("oriented.xyz")) + " " + q(file("o.ply")) + " --radius 0.2 --orient scanner" + limit);
      CHECK(r.status == 0);
      CHECK(r.out.find("valid       3000 (100.00 %)") != std::string::npos);
    }
  }
  {
    const Run r = run_tool(q(file("f3.las")) + " " + q(file("x.ply")) + " --radius 0.5 --orient scanner");
    CHECK(r.status == 2);
    CHECK(r.err.find("--orient scanner: ") != std::string::npos);
    CHECK(r.err.find("holds no pulse directions") != std::string::npos);
  }

  // header bounds that do not hold the points: read, with a warning
  std::string wrong_bounds = good;
  put_le<double>(wrong_bounds, 179, 1e6 + 4.0);  // max x below the sphere's 1e6 + 5
  write_text(file("bounds.las"), wrong_bounds);
  const Run w = run_tool(q(file("bounds.las")) + " " + q(file("bounds.ply")) + " --radius 0.5" + viewpoint);
  CHECK(w.status == 0);
  CHECK(w.err.find("is not within the header's bounds") != std::string::npos);
  // with every digit the numbers need (issue 28: six digits printed "[999999, 1e+06] is not
  // within the header's bounds [999999, 1e+06]"): "x range [LO, HI] is not within the
  // header's bounds [LO', HI']", each reading back as the exact value
  double quantised_max = -HUGE_VAL;
  for(const Oriented_point& p : pts)
    quantised_max = std::max(quantised_max, double(std::lround((p.first.x() - offset[0]) / 0.001)) * 0.001 + offset[0]);
  auto bracket = [&](const std::string& before) {
    const std::size_t at = w.err.find(before);
    REQUIRE(at != std::string::npos);
    const std::size_t open = at + before.size(), comma = w.err.find(", ", open), close = w.err.find(']', open);
    return std::make_pair(w.err.substr(open, comma - open), w.err.substr(comma + 2, close - comma - 2));
  };
  const auto range = bracket("x range ["), bounds = bracket("header's bounds [");
  INFO(w.err);
  CHECK(std::stod(range.second) == quantised_max);
  CHECK(std::stod(bounds.second) == 1e6 + 4.0);
  CHECK(range.second != bounds.second);
  CHECK(bounds.second == "1000004");
}

// ---------------------------------------------------------------------------------------
// LAS output, extra bytes, geographic coordinates, truncated files (issue 28)

namespace {

// The values of column `name` of a CSV file with a header line.
std::vector<double> csv_values(const std::string& csv, const std::string& name)
{
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  for(std::size_t b = 0;;)
  {
    const std::size_t comma = line.find(',', b);
    names.push_back(line.substr(b, comma == std::string::npos ? std::string::npos : comma - b));
    if(comma == std::string::npos)
      break;
    b = comma + 1;
  }
  const std::size_t column = std::size_t(std::find(names.begin(), names.end(), name) - names.begin());
  INFO("CSV column " << name << " in " << names.size() << " columns");
  REQUIRE(column < names.size());
  std::vector<double> values;
  while(std::getline(in, line))
  {
    std::size_t b = 0;
    for(std::size_t c = 0; c < column; ++c)
      b = line.find(',', b) + 1;
    values.push_back(std::strtod(line.c_str() + b, nullptr));
  }
  return values;
}

// A LAS 1.2 file of format 3 whose records end with 8 extra bytes described by an extra-bytes
// VLR: Amplitude (float, 0.5 i), Reflectance (int16 with scale 0.01: raw i % 2000 - 1000),
// Deviation (uint16, 7 i); and a GeoTIFF key of a projected CRS.
std::string las_with_extra_bytes(const std::vector<Oriented_point>& pts, const double offset[3],
                                 std::vector<std::array<double, 3> >* quantised)
{
  using namespace psc_las_test;
  std::string in = las_file(pts, 3, 2, 0.001, offset, 8, quantised);
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    const std::size_t r = 227 + i * 42 + 34;
    set_le<float>(in, r, 0.5f * float(i));
    set_le<std::int16_t>(in, r + 4, std::int16_t(int(i % 2000) - 1000));
    set_le<std::uint16_t>(in, r + 6, std::uint16_t(i * 7));
  }
  const std::string descriptors = descriptor(9, "Amplitude") +
                                  descriptor(4, "Reflectance", 8, 0.01, 0, "reflectance dB") +
                                  descriptor(3, "Deviation");
  return with_vlrs(in, {vlr("LASF_Projection", 34735, geokeys(1)), vlr("LASF_Spec", 4, descriptors)});
}

// The LAS file the tool writes from `input` to `output` (names in the work directory) with
// `options`; the run must succeed.
psc_las_test::Las las_output(const std::string& input, const std::string& output, const std::string& options)
{
  const Run r = run_tool(q(file(input)) + " " + q(file(output)) + " " + options);
  INFO(r.err);
  REQUIRE(r.status == 0);
  return psc_las_test::read_las_1_4(read_text(file(output)));
}

}  // namespace

TEST_CASE("tool: LAS output is LAS 1.4 with the estimates as extra bytes, per an independent reader of the "
          "specification, tiles give the same bytes, read back")
{
  using namespace psc_las_test;
  ::setenv("SOURCE_DATE_EPOCH", "1700000000", 1);  // 2023-11-14, day 318: reproducible headers
  const double offset[3] = {1e6, 2e6, 100};
  std::vector<Oriented_point> pts;
  for(const Oriented_point& p : sphere(3000, 2.0))
    pts.emplace_back(Point(p.first.x() + 1e6 + 3, p.first.y() + 2e6 + 4, p.first.z() + 105), p.second);
  pts.emplace_back(Point(1e6 + 30, 2e6 + 4, 105), Vector(0, 0, 1));  // isolated: invalid
  const std::size_t n = pts.size();
  std::vector<std::array<double, 3> > quantised;
  const std::string in = las_with_extra_bytes(pts, offset, &quantised);
  write_text(file("eb.las"), in);
  const std::string viewpoint = " --orient viewpoint:1000003,2000004,105";  // normals inwards: H = -1/2
  const Run r = run_tool(q(file("eb.las")) + " " + q(file("eb_out.las")) + " --radius 0.5" + viewpoint);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("valid       3000 (99.97 %)") != std::string::npos);
  CHECK(r.err.find("meaningless") == std::string::npos);  // a projected CRS: no warning
  const Las l = read_las_1_4(read_text(file("eb_out.las")));
  CHECK(l.major == 1);
  CHECK(l.minor == 4);
  CHECK(l.header_size == 375);
  CHECK(l.format == 3);  // the input's
  CHECK(l.software == "point_set_curvatures");
  CHECK(l.day == 318);
  CHECK(l.year == 2023);
  CHECK(l.count == n);
  CHECK(l.legacy_count == n);  // format 0-5, the count fits
  CHECK(l.by_return[0] == n);  // every point is return 1 of 2
  CHECK(l.legacy_by_return[0] == n);
  CHECK(l.by_return[1] == 0);
  CHECK(l.first_evlr == 0);
  CHECK(l.evlr_count == 0);
  for(int a = 0; a < 3; ++a)
  {
    CHECK(l.scale[a] == 0.001);
    CHECK(l.offset[a] == offset[a]);
    double lo = 1e300, hi = -1e300;
    for(const auto& x : quantised)
    {
      lo = std::min(lo, x[a]);
      hi = std::max(hi, x[a]);
    }
    CHECK(l.min[a] == lo);
    CHECK(l.max[a] == hi);
  }
  // the VLRs: the input's GeoTIFF keys, then the extra-bytes VLR of the output
  REQUIRE(l.vlrs.size() == 2);
  CHECK(l.vlrs[0].user_id == "LASF_Projection");
  CHECK(l.vlrs[0].record_id == 34735);
  CHECK(l.vlrs[0].payload == geokeys(1));
  CHECK(l.vlrs[1].user_id == "LASF_Spec");
  CHECK(l.vlrs[1].record_id == 4);
  const std::vector<std::string> names = {
    "nx",        "ny",     "nz",        "k_min",       "k_max",    "mean",   "gaussian",
    "dmin_x",    "dmin_y", "dmin_z",    "dmax_x",      "dmax_y",   "dmax_z", "normal_coherence",
    "neighbors", "valid",  "Amplitude", "Reflectance", "Deviation"};
  REQUIRE(l.descriptors.size() == names.size());
  for(std::size_t k = 0; k < names.size(); ++k)
  {
    const Descriptor& d = l.descriptors[k];
    INFO(names[k]);
    CHECK(d.name == names[k]);
    CHECK(d.bytes.substr(0, 2) == std::string(2, '\0'));  // reserved
    const int type = k < 14 ? 10 : k == 14 ? 6 : k == 15 ? 1 : k == 16 ? 9 : k == 17 ? 4 : 3;
    CHECK(d.data_type == type);
    if(k < 14)
    {
      CHECK(d.options == 1);  // no_data
      CHECK(std::isnan(le<double>(d.no_data, 0)));
      CHECK(!d.description.empty());
    }
    else if(k == 17)
    {
      CHECK(d.options == 8);  // scale, as in the input
      CHECK(d.scale == 0.01);
      CHECK(d.description == "reflectance dB");
    }
    else
      CHECK(d.options == 0);
  }
  CHECK(l.descriptors[5].description == "mean curvature (k_min+k_max)/2");
  CHECK(l.point_offset == 375 + 54 + 16 + 54 + 192 * names.size());
  CHECK(l.record_length == 34 + 14 * 8 + 4 + 1 + 4 + 2 + 2);
  REQUIRE(l.file.size() == l.point_offset + n * l.record_length);
  std::size_t mean_at = 0, valid_at = 0, neighbors_at = 0, amplitude_at = 0, reflectance_at = 0, deviation_at = 0;
  REQUIRE(l.extra("mean", mean_at));
  REQUIRE(l.extra("valid", valid_at));
  REQUIRE(l.extra("neighbors", neighbors_at));
  REQUIRE(l.extra("Amplitude", amplitude_at));
  REQUIRE(l.extra("Reflectance", reflectance_at));
  REQUIRE(l.extra("Deviation", deviation_at));
  const std::size_t in_offset = le<std::uint32_t>(in, 96);
  std::size_t wrong_standard = 0, wrong_extra = 0;
  double worst_h = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::string rec = l.record(i);
    // every standard field as in the input: the same 34 bytes
    wrong_standard += rec.substr(0, 34) != in.substr(in_offset + i * 42, 34);
    wrong_extra += le<float>(rec, amplitude_at) != 0.5f * float(i) ||
                   le<std::int16_t>(rec, reflectance_at) != int(i % 2000) - 1000 ||
                   le<std::uint16_t>(rec, deviation_at) != std::uint16_t(i * 7);
    const double mean = le<double>(rec, mean_at);
    if(i < 3000)
    {
      wrong_extra += le<std::uint8_t>(rec, valid_at) != 1 || le<std::int32_t>(rec, neighbors_at) < 20;
      worst_h = std::max(worst_h, std::abs(mean + 0.5));
    }
    else  // the isolated point: no_data
      wrong_extra += le<std::uint8_t>(rec, valid_at) != 0 || !std::isnan(mean);
  }
  CHECK(wrong_standard == 0);
  CHECK(wrong_extra == 0);
  CHECK(worst_h < 0.05);

  // in tiles: the same bytes
  const Run tiled =
    run_tool(q(file("eb.las")) + " " + q(file("eb_tiled.las")) + " --radius 0.5 --orient +z --memory-limit 1200K");
  const Run whole = run_tool(q(file("eb.las")) + " " + q(file("eb_whole.las")) + " --radius 0.5 --orient +z");
  REQUIRE(tiled.status == 0);
  REQUIRE(whole.status == 0);
  CHECK(tiled.out.find("  tiles") != std::string::npos);
  CHECK(read_text(file("eb_tiled.las")) == read_text(file("eb_whole.las")));

  // --float: float32 estimates with a NaN no_data (a double, as the specification upcasts floats)
  const Las f = las_output("eb.las", "eb_float.las", "--radius 0.5 --float --quiet" + viewpoint);
  REQUIRE(f.descriptors.size() == names.size());
  CHECK(f.descriptors[5].data_type == 9);
  CHECK(f.descriptors[5].options == 1);
  CHECK(std::isnan(le<double>(f.descriptors[5].no_data, 0)));
  CHECK(f.record_length == 34 + 14 * 4 + 4 + 1 + 4 + 2 + 2);
  std::size_t float_mean_at = 0;
  REQUIRE(f.extra("mean", float_mean_at));
  CHECK(le<float>(f.record(7), float_mean_at) == float(le<double>(l.record(7), mean_at)));

  // read back by the tool's reader: the estimates and the extra bytes as attributes
  REQUIRE(
    run_tool(q(file("eb_out.las")) + " " + q(file("back.csv")) + " --radius 0.5 --fields mean --quiet" + viewpoint)
      .status == 0);
  const std::string back = read_text(file("back.csv"));
  const std::vector<double> input_mean = csv_values(back, "input_mean"), amplitude = csv_values(back, "Amplitude"),
                            reflectance = csv_values(back, "Reflectance"), deviation = csv_values(back, "Deviation"),
                            x = csv_values(back, "x");
  REQUIRE(input_mean.size() == n);
  std::size_t wrong_back = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const double m = le<double>(l.record(i), mean_at);
    wrong_back += !(m == input_mean[i] || (std::isnan(m) && std::isnan(input_mean[i]))) ||
                  amplitude[i] != 0.5 * double(i) || std::abs(reflectance[i] - 0.01 * (int(i % 2000) - 1000)) > 1e-12 ||
                  deviation[i] != double(i * 7 % 65536) || x[i] != quantised[i][0];
  }
  CHECK(wrong_back == 0);

  // a text input: format 6, return 1 of 1, the offset at the floor of the minimum, a scale of
  // a million steps or more across the extent (4: 1e-6)
  std::vector<Oriented_point> ball;
  for(const Oriented_point& p : sphere(2000, 2.0))
    ball.emplace_back(Point(p.first.x() + 10.5, p.first.y() + 20.5, p.first.z() + 30.5), p.second);
  write_xyz(file("ball.xyz"), ball);
  const Las b = las_output("ball.xyz", "ball.las", "--radius 0.5 --fields mean,valid --quiet");
  CHECK(b.format == 6);
  CHECK(b.legacy_count == 0);  // formats 6-10: the legacy counts are 0
  CHECK(b.count == ball.size());
  CHECK(b.by_return[0] == ball.size());
  CHECK(b.system_id == "OTHER");
  CHECK(b.record_length == 30 + 8 + 1);
  REQUIRE(b.vlrs.size() == 1);
  REQUIRE(b.descriptors.size() == 2);
  double lo[3] = {1e300, 1e300, 1e300};
  for(const Oriented_point& p : ball)
    for(int a = 0; a < 3; ++a)
      lo[a] = std::min(lo[a], p.first[a]);
  std::size_t wrong_ball = 0;
  for(int a = 0; a < 3; ++a)
  {
    CHECK(b.offset[a] == std::floor(lo[a]));
    CHECK(b.scale[a] == 1e-6);
  }
  double worst_ball = 0;
  std::size_t ball_mean_at = 0;
  REQUIRE(b.extra("mean", ball_mean_at));
  for(std::size_t i = 0; i < ball.size(); ++i)
  {
    for(int a = 0; a < 3; ++a)
      wrong_ball += std::abs(b.coordinate(i, a) - ball[i].first[a]) > 0.5e-6 * (1 + 1e-9);
    wrong_ball += b.record(i)[14] != char(0x11);  // return 1 of 1
    worst_ball = std::max(worst_ball, std::abs(le<double>(b.record(i), ball_mean_at) - 0.5));
  }
  CHECK(wrong_ball == 0);
  CHECK(worst_ball < 0.01);

  // in tiles, the scale and offset from the same bounds: the same bytes
  const Run ball_tiled = run_tool(q(file("ball.xyz")) + " " + q(file("ball_tiled.las")) +
                                  " --radius 0.5 --fields mean,valid --memory-limit 100K");
  REQUIRE(ball_tiled.status == 0);
  CHECK(ball_tiled.out.find("  tiles") != std::string::npos);
  CHECK(read_text(file("ball_tiled.las")) == read_text(file("ball.las")));
  // a point with a non-finite coordinate: at the offset, withheld, out of the bounds, warned of
  {
    std::ofstream add(file("ball.xyz"), std::ios::app);
    add << "nan 20 30 0 0 1\n";
  }
  const Run nan_run =
    run_tool(q(file("ball.xyz")) + " " + q(file("ball_nan.las")) + " --radius 0.5 --fields mean,valid");
  REQUIRE(nan_run.status == 0);
  CHECK(
    nan_run.err.find("1 points with non-finite coordinates are written to the LAS output at its offset, withheld") !=
    std::string::npos);
  const Las bn = read_las_1_4(read_text(file("ball_nan.las")));
  REQUIRE(bn.count == ball.size() + 1);
  CHECK((bn.record(ball.size())[15] & 4) == 4);  // withheld (formats 6-10: bit 2 of byte 15)
  CHECK((bn.record(0)[15] & 4) == 0);
  CHECK(bn.coordinate(ball.size(), 0) == bn.offset[0]);
  for(int a = 0; a < 3; ++a)
  {
    CHECK(bn.min[a] == b.min[a]);
    CHECK(bn.max[a] == b.max[a]);
  }
  // --drop-attributes: a LAS input's standard fields stay, its extra bytes go
  const Las dropped =
    las_output("eb.las", "eb_drop.las", "--radius 0.5 --fields mean --drop-attributes --quiet" + viewpoint);
  REQUIRE(dropped.descriptors.size() == 1);
  CHECK(dropped.descriptors[0].name == "mean");
  CHECK(dropped.format == 3);
  CHECK(dropped.record_length == 34 + 8);
  CHECK(dropped.record(42).substr(0, 34) == in.substr(in_offset + 42 * 42, 34));

  // LAS 1.4 format 6 with a WKT CRS in an extended VLR: copied after the points, the WKT bit kept
  std::string v14 = las_file(pts, 6, 4, 0.001, offset);
  const std::string wkt = "PROJCS[\"WGS 84 / UTM zone 32N\",GEOGCS[\"WGS 84\"],UNIT[\"metre\",1]]";
  set_le<std::uint16_t>(v14, 6, 16);  // WKT
  set_le<std::uint64_t>(v14, 235, v14.size());
  set_le<std::uint32_t>(v14, 243, 1);
  v14 += evlr("LASF_Projection", 2112, wkt + std::string(1, '\0'));
  write_text(file("evlr.las"), v14);
  const Run e =
    run_tool(q(file("evlr.las")) + " " + q(file("evlr_out.las")) + " --radius 0.5 --fields mean" + viewpoint);
  INFO(e.err);
  REQUIRE(e.status == 0);
  CHECK(e.err.find("meaningless") == std::string::npos);
  const Las el = read_las_1_4(read_text(file("evlr_out.las")));
  CHECK(el.format == 6);
  CHECK(el.global_encoding == 16);
  CHECK(el.legacy_count == 0);
  REQUIRE(el.evlr_count == 1);
  CHECK(el.first_evlr == el.point_offset + n * el.record_length);
  REQUIRE(el.evlrs.size() == 1);
  CHECK(el.evlrs[0].user_id == "LASF_Projection");
  CHECK(el.evlrs[0].record_id == 2112);
  CHECK(el.evlrs[0].payload == wkt + std::string(1, '\0'));
  CHECK(el.file.size() == el.first_evlr + 60 + wkt.size() + 1);
  CHECK(el.record(5).substr(0, 30) == v14.substr(375 + 5 * 30, 30));

  // an extra-bytes descriptor held in an EVLR (not read, not copied: the output's VLR
  // describes its own fields) beside another EVLR: the file ends where the copied EVLR ends (the reserved size
  // counted both: a file cut at the reservation had zeros after its end)
  {
    std::string eb = las_file(pts, 6, 4, 0.001, offset, 4);
    for(std::size_t i = 0; i < n; ++i)
      set_le<float>(eb, 375 + i * 34 + 30, 0.25f * float(i));
    set_le<std::uint64_t>(eb, 235, eb.size());
    set_le<std::uint32_t>(eb, 243, 2);
    const std::string mine(100, 'x');
    eb += evlr("LASF_Spec", 4, descriptor(9, "Amplitude")) + evlr("MyStuff", 7, mine);
    write_text(file("evlr_eb.las"), eb);
    const Las l = las_output("evlr_eb.las", "evlr_eb_out.las", "--radius 0.5 --fields mean" + viewpoint);
    REQUIRE(l.evlr_count == 1);
    REQUIRE(l.evlrs.size() == 1);
    CHECK(l.evlrs[0].user_id == "MyStuff");
    CHECK(l.file.size() == l.first_evlr + 60 + mine.size());
    CHECK(l.first_evlr == l.point_offset + n * l.record_length);
    CHECK(l.record_length == 30 + 8);  // mean as double; the undescribed extra bytes are not kept
  }

  // every point format 0-10: the standard fields of each record written back bytewise (flags,
  // scan angles, GPS times, colours, NIR, wave packets with their byte offsets and pulses)
  {
    static const std::size_t standard[11] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
    const std::vector<Oriented_point> few(pts.begin(), pts.begin() + 400);
    const double centre[3] = {1e6 + 3, 2e6 + 4, 105};
    for(int format = 0; format <= 10; ++format)
    {
      INFO("point format " << format);
      const int minor = format >= 6 ? 4 : format >= 4 ? 3 : 2;
      std::string src = las_file(few, format, minor, 0.001, offset, 0, nullptr, centre);
      const std::size_t header = le<std::uint16_t>(src, 94);
      if(format == 4 || format == 5 || format == 9 || format == 10)
        for(std::size_t i = 0; i < few.size(); ++i)
          set_le<std::uint64_t>(src,
                                header + i * standard[format] +
                                  (format == 4   ? 28
                                   : format == 5 ? 34
                                   : format == 9 ? 30
                                                 : 38) +
                                  1,
                                std::uint64_t(1000 + 256 * i));
      write_text(file("fmt.las"), src);
      const Las fl = las_output("fmt.las", "fmt_out.las", "--radius 0.5 --fields mean --quiet" + viewpoint);
      CHECK(fl.format == format);
      CHECK(fl.record_length == standard[format] + 8);
      CHECK(fl.legacy_count == (format <= 5 ? few.size() : 0));
      std::size_t different = 0;
      for(std::size_t i = 0; i < few.size(); ++i)
        different +=
          fl.record(i).substr(0, standard[format]) != src.substr(header + i * standard[format], standard[format]);
      CHECK(different == 0);
    }
  }

  // refused before any work: --color and --ascii with a .las output
  for(const char* option : {" --color mean", " --ascii"})
  {
    const Run bad = run_tool(q(file("eb.las")) + " " + q(file("bad.las")) + option);
    CHECK(bad.status == 2);
    CHECK(std::count(bad.err.begin(), bad.err.end(), '\n') == 1);
    CHECK(!fs::exists(file("bad.las")));
  }
  ::unsetenv("SOURCE_DATE_EPOCH");
}

namespace {

// 1,500 points of a sphere of radius 2 about (1e6 + 3, 2e6 + 4, 105), as LiDAR coordinates are.
std::vector<Oriented_point> sphere_in_lidar_coordinates()
{
  std::vector<Oriented_point> pts;
  for(const Oriented_point& p : sphere(1500, 2.0))
    pts.emplace_back(Point(p.first.x() + 1e6 + 3, p.first.y() + 2e6 + 4, p.first.z() + 105), p.second);
  return pts;
}

}  // namespace

TEST_CASE("tool: LAS extra bytes are read in their types (float Amplitude, int16 Reflectance with a scale, uint16 "
          "Deviation) and carried to PLY and CSV, deprecated and undocumented ones are warned of")
{
  using namespace psc_las_test;
  const double offset[3] = {1e6, 2e6, 100};
  const std::vector<Oriented_point> pts = sphere_in_lidar_coordinates();
  write_text(file("eb2.las"), las_with_extra_bytes(pts, offset, nullptr));
  const Run r = run_tool(q(file("eb2.las")) + " " + q(file("eb2.ply")) + " --radius 0.5 --orient +z");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.err.find("extra bytes") == std::string::npos);  // every extra byte described and read
  const std::string ply = read_text(file("eb2.ply"));
  CHECK(ply.find("property float Amplitude\nproperty double Reflectance\nproperty ushort Deviation\n") !=
        std::string::npos);
  Point_set ps;
  REQUIRE(CGAL::IO::read_PLY(file("eb2.ply"), ps));
  REQUIRE(ps.size() == pts.size());
  const auto amplitude = property<float>(ps, "Amplitude");
  const auto reflectance = property<double>(ps, "Reflectance");
  const auto deviation = property<std::uint16_t>(ps, "Deviation");
  std::size_t i = 0, wrong = 0;
  for(Point_set::Index p : ps)
  {
    wrong += amplitude[p] != 0.5f * float(i) || reflectance[p] != double(int(i % 2000) - 1000) * 0.01 ||
             deviation[p] != std::uint16_t(i * 7);
    ++i;
  }
  CHECK(wrong == 0);
  REQUIRE(run_tool(q(file("eb2.las")) + " " + q(file("eb2.csv")) + " --radius 0.5 --orient +z --fields mean --quiet")
            .status == 0);
  const std::string csv = read_text(file("eb2.csv"));
  CHECK(csv.substr(0, csv.find('\n')).find(",gps_time,red,green,blue,Amplitude,Reflectance,Deviation") !=
        std::string::npos);
  CHECK(csv_values(csv, "Reflectance")[3] == -9.97);
  CHECK(csv_values(csv, "Deviation")[1499] == 1499 * 7);

  // a deprecated array type (13: two ushorts) and 2 undocumented bytes: skipped, with warnings
  std::string odd = las_file(pts, 1, 2, 0.001, offset, 8);
  for(std::size_t k = 0; k < pts.size(); ++k)
    set_le<std::uint16_t>(odd, 227 + k * 36 + 28 + 4, std::uint16_t(k));
  odd = with_vlrs(odd, {vlr("LASF_Spec", 4, descriptor(13, "Pair") + descriptor(3, "Width"))});
  write_text(file("odd.las"), odd);
  const Run o = run_tool(q(file("odd.las")) + " " + q(file("odd.csv")) + " --radius 0.5 --orient +z --fields mean");
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(o.err.find("extra bytes fields not read: 'Pair' (deprecated array type)") != std::string::npos);
  CHECK(o.err.find("2 extra bytes per point record beyond those the extra-bytes VLR describes are not read") !=
        std::string::npos);
  const std::vector<double> width = csv_values(read_text(file("odd.csv")), "Width");
  REQUIRE(width.size() == pts.size());
  CHECK(width[1234] == 1234);
}

TEST_CASE("tool: a geographic LAS (GeoTIFF key, WKT GEOGCS, or x y like degrees) gets one warning naming the "
          "reprojection, a projected one none")
{
  using namespace psc_las_test;
  const double offset[3] = {1e6, 2e6, 100};
  const std::vector<Oriented_point> pts = sphere_in_lidar_coordinates();
  const std::string base = las_file(pts, 1, 2, 0.001, offset);
  const std::string wkt = "GEOGCS[\"WGS 84\",DATUM[\"WGS_1984\"],UNIT[\"degree\",0.0174532925199433]]";
  // a lon/lat terrain: 0.01 degree wide, 30 m high
  std::vector<Oriented_point> terrain;
  for(int u = 0; u < 40; ++u)
    for(int v = 0; v < 40; ++v)
      terrain.emplace_back(
        Point(7.1 + 0.00025 * u, 46.2 + 0.00025 * v, 500 + 15 * std::sin(0.2 * u) * std::cos(0.15 * v)),
        Vector(0, 0, 1));
  const double geo_offset[3] = {7, 46, 0};
  const std::pair<std::string, std::string> cases[] = {
    {with_vlrs(base, {vlr("LASF_Projection", 34735, geokeys(2))}), "GTModelTypeGeoKey 1024 = 2"},
    {with_vlrs(base, {vlr("LASF_Projection", 2112, wkt)}), "WKT GEOGCS"},
    {las_file(terrain, 1, 2, 1e-7, geo_offset), "x and y look like longitude and latitude (x in [7.1, 7.10975]"},
    {with_vlrs(base, {vlr("LASF_Projection", 34735, geokeys(1))}), ""},
    {base, ""}};
  int k = 0;
  for(const auto& c : cases)
  {
    INFO("case " << k);
    const std::string las = file("geo" + std::to_string(k++) + ".las");
    write_text(las, c.first);
    const Run r = run_tool(q(las) + " " + q(file("geo.ply")) + " --radius 0.5 --orient +z");
    INFO(r.err);
    REQUIRE(r.status == 0);
    const std::size_t at = r.err.find("curvatures in 1/degree are meaningless");
    if(c.second.empty())
      CHECK(at == std::string::npos);
    else
    {
      REQUIRE(at != std::string::npos);
      CHECK(r.err.find(c.second) != std::string::npos);
      // one line, naming what to do
      const std::size_t begin = r.err.rfind('\n', at) + 1, end = r.err.find('\n', at);
      const std::string line = r.err.substr(begin, end - begin);
      CHECK(line.find("reproject to a projected CRS in metres") != std::string::npos);
      CHECK(line.find("pdal translate IN.las OUT.las reprojection --filters.reprojection.out_srs=EPSG:326xx") !=
            std::string::npos);
      CHECK(line.find("--radius in degrees") != std::string::npos);
    }
  }
}

TEST_CASE("tool: a truncated LAS is refused, and read to its last complete record with --allow-truncated and a warning")
{
  const double offset[3] = {0, 0, 0};
  const std::vector<Oriented_point> pts = sphere(1065, 2.0);
  std::string las = las_file(pts, 1, 2, 0.001, offset);
  las.resize(las.size() - 10);  // 1064 complete records
  write_text(file("cut.las"), las);
  const Run refused = run_tool(q(file("cut.las")) + " " + q(file("cut.ply")) + " --radius 0.5");
  CHECK(refused.status == 2);
  CHECK(refused.err.find("truncated: the header declares 1065 points") != std::string::npos);
  CHECK(refused.err.find("(1064 complete records: --allow-truncated reads them)") != std::string::npos);
  CHECK(std::count(refused.err.begin(), refused.err.end(), '\n') == 1);
  CHECK(!fs::exists(file("cut.ply")));
  const Run r = run_tool(q(file("cut.las")) + " " + q(file("cut.ply")) + " --radius 0.5 --orient +z --allow-truncated");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.err.find("truncated: read the 1064 complete points of the 1065 the header declares (--allow-truncated)") !=
        std::string::npos);
  CHECK(r.out.find("points      1064") != std::string::npos);
  Point_set ps;
  REQUIRE(CGAL::IO::read_PLY(file("cut.ply"), ps));
  CHECK(ps.size() == 1064);
  // to LAS: the count written is the points read
  const psc_las_test::Las l =
    las_output("cut.las", "cut_out.las", "--radius 0.5 --orient +z --allow-truncated --quiet");
  CHECK(l.count == 1064);
  CHECK(l.legacy_count == 1064);
  CHECK(l.file.size() == l.point_offset + 1064 * std::size_t(l.record_length));
}

TEST_CASE("tool: input attributes carried in their types, renamed on a clash, --fields, --float, --drop-attributes")
{
  const std::vector<Oriented_point> pts = sphere(800, 1.0);
  std::ostringstream ply;
  ply.precision(17);
  ply << "ply\nformat ascii 1.0\nelement vertex " << pts.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nproperty float nx\nproperty float ny\n"
         "property float nz\nproperty uchar red\nproperty float intensity\nproperty short k_min\nend_header\n";
  for(std::size_t i = 0; i < pts.size(); ++i)
    ply << pts[i].first.x() << " " << pts[i].first.y() << " " << pts[i].first.z() << " " << pts[i].second.x() << " "
        << pts[i].second.y() << " " << pts[i].second.z() << " " << i % 256 << " " << 0.5 * double(i) << " " << -int(i)
        << "\n";
  write_text(file("attr.ply"), ply.str());
  REQUIRE(run_tool(q(file("attr.ply")) + " " + q(file("attr_out.ply")) + " --radius 0.3 --color mean --quiet").status ==
          0);
  Point_set ps;
  REQUIRE(CGAL::IO::read_PLY(file("attr_out.ply"), ps));
  const auto red_in = property<std::uint8_t>(ps, "input_red");  // red is --color's
  const auto intensity = property<float>(ps, "intensity");
  const auto k_min_in = property<std::int16_t>(ps, "input_k_min");  // k_min is the estimate's
  const auto k_min = property<double>(ps, "k_min");
  std::size_t i = 0, wrong = 0;
  for(Point_set::Index p : ps)
  {
    wrong += red_in[p] != i % 256 || intensity[p] != float(0.5 * double(i)) || k_min_in[p] != -int(i) ||
             std::abs(k_min[p] - 1) > 0.05;
    ++i;
  }
  CHECK(wrong == 0);

  // --fields: x y z and the fields named, in the tool's order; --float: float32 estimates,
  // double positions; CSV the same columns
  REQUIRE(run_tool(q(file("attr.ply")) + " " + q(file("fields.ply")) +
                   " --radius 0.3 --fields valid,mean,dmin --float --drop-attributes --quiet")
            .status == 0);
  const std::string fields = read_text(file("fields.ply"));
  const std::string header = fields.substr(0, fields.find("end_header"));
  CHECK(header.find("property double x\nproperty double y\nproperty double z\nproperty float mean\n"
                    "property float dmin_x\nproperty float dmin_y\nproperty float dmin_z\nproperty uchar valid\n") !=
        std::string::npos);
  CHECK(header.find("intensity") == std::string::npos);
  CHECK(header.find("k_min") == std::string::npos);
  // 3 doubles + 4 floats + 1 byte per point
  CHECK(fields.size() - fields.find("end_header\n") - 11 == pts.size() * (24 + 16 + 1));
  REQUIRE(run_tool(q(file("attr.ply")) + " " + q(file("fields.csv")) + " --radius 0.3 --fields mean --quiet").status ==
          0);
  const std::string csv = read_text(file("fields.csv"));
  CHECK(csv.substr(0, csv.find('\n')) == "x,y,z,mean,red,intensity,input_k_min");
  const Run bad = run_tool(q(file("attr.ply")) + " " + q(file("x.ply")) + " --fields mean,curvedness");
  CHECK(bad.status == 2);
  CHECK(bad.err.find("--fields: unknown field 'curvedness'") != std::string::npos);

  // text columns named by a header line are attributes too
  std::ostringstream txt;
  txt.precision(17);
  txt << "x y z nx ny nz reflectance _\n";
  for(std::size_t k = 0; k < pts.size(); ++k)
    txt << pts[k].first.x() << " " << pts[k].first.y() << " " << pts[k].first.z() << " " << pts[k].second.x() << " "
        << pts[k].second.y() << " " << pts[k].second.z() << " " << 0.25 * double(k) << " 9\n";
  write_text(file("attr.txt"), txt.str());
  REQUIRE(
    run_tool(q(file("attr.txt")) + " " + q(file("attr_txt.csv")) + " --radius 0.3 --fields mean --quiet").status == 0);
  const std::string out = read_text(file("attr_txt.csv"));
  CHECK(out.substr(0, out.find('\n')) == "x,y,z,mean,reflectance");
  CHECK(out.find(",199.75\n") != std::string::npos);  // the last point's reflectance
}

// The columns come from the package's table of fields (field_descriptions.h), by name: the CSV
// header is x y z and the table's names in its order (mean_error with the automatic scale
// only), each value under its own name (the unit sphere: mean 1), a --fields group is its
// components, --color the table's summarised curvatures, a LAS extra bytes' description its row's.
TEST_CASE("tool: the output's columns are the package's table of fields, in its order, by name")
{
  namespace PSC = CGAL::Point_set_curvatures;
  write_xyz(file("table.xyz"), sphere(1000, 1.0));
  for(const bool automatic : {false, true})
  {
    INFO("automatic scale " << automatic);
    REQUIRE(
      run_tool(q(file("table.xyz")) + " " + q(file("table.csv")) + (automatic ? "" : " --neighbors 40") + " --quiet")
        .status == 0);
    std::string expected = "x,y,z";
    for(const PSC::Field_description& f : PSC::field_descriptions)
      if(f.name && (automatic || !f.automatic_scale_only))
        expected += std::string(",") + f.name;
    std::istringstream csv(read_text(file("table.csv")));
    std::string header, row;
    REQUIRE(std::getline(csv, header));
    REQUIRE(std::getline(csv, row));
    CHECK(header == expected);
    std::map<std::string, double> value;
    std::istringstream names(header), values(row);
    for(std::string name, v; std::getline(names, name, ',') && std::getline(values, v, ',');)
      value[name] = std::stod(v);
    CHECK(std::abs(value.at("mean") - 1) < 0.05);
    CHECK(std::abs(value.at("gaussian") - 1) < 0.1);
    CHECK(std::abs(std::hypot(value.at("nx"), value.at("ny"), value.at("nz")) - 1) < 1e-9);
    CHECK(value.at("valid") == 1);
    CHECK(value.at("neighbors") >= 40);
    CHECK(value.count("mean_error") == (automatic ? 1u : 0u));
  }
  REQUIRE(run_tool(q(file("table.xyz")) + " " + q(file("group.csv")) + " --neighbors 40 --fields dmax,normal --quiet")
            .status == 0);
  const std::string group = read_text(file("group.csv"));
  CHECK(group.substr(0, group.find('\n')) == "x,y,z,nx,ny,nz,dmax_x,dmax_y,dmax_z");
  for(const char* bad : {"k_min,", "' '"})
  {
    INFO("--fields " << bad);
    const Run r = run_tool(q(file("table.xyz")) + " " + q(file("bad.csv")) + " --neighbors 40 --fields " + bad);
    CHECK(r.status == 2);
    CHECK(r.err.find("--fields: unknown field ''") != std::string::npos);
  }
  // --color: the summarised fields, named in the message of an unknown one
  std::string summarised;
  for(const PSC::Field_description& f : PSC::field_descriptions)
    if(f.name && f.summarised)
      summarised += (summarised.empty() ? "" : "|") + std::string(f.name);
  const Run color = run_tool(q(file("table.xyz")) + " " + q(file("c.ply")) + " --neighbors 40 --color curvedness");
  CHECK(color.status == 2);
  CHECK(color.err.find("(available: " + summarised + ")") != std::string::npos);
  REQUIRE(run_tool(q(file("table.xyz")) + " " + q(file("table.las")) + " --neighbors 40 --quiet").status == 0);
  const std::string las = read_text(file("table.las"));
  for(const PSC::Field_description& f : PSC::field_descriptions)
    if(f.name && !f.automatic_scale_only)
    {
      INFO(f.name);
      CHECK(las.find(std::string(f.description)) != std::string::npos);
    }
}
