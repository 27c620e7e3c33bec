// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Inputs larger than --memory-limit (issues 12 and 30): tiles bitwise as the whole run, by radius and
// by count, in every format; adversarial tiles; signals in every phase; the progress line; peak memory.

#include "test_tool_support.h"

using namespace psc_tool_test;

// ---------------------------------------------------------------------------------------
// Inputs larger than --memory-limit: estimated in tiles, bitwise as in memory (issue 12)

TEST_CASE("tool: --memory-limit tiles give the in-memory output bitwise, by radius and by count, PLY CSV and ASCII, "
          "attributes, invalid points, colours")
{
  // density varying 1:10 (the halo by count differs across the cloud), an attribute, a
  // point far away (too few neighbours), a zero normal, a NaN coordinate
  std::vector<Oriented_point> pts = varying_density(6000, 11);
  std::ostringstream ply;
  ply.precision(17);
  ply << "ply\nformat ascii 1.0\nelement vertex " << pts.size() + 3
      << "\nproperty double x\nproperty double y\nproperty double z\nproperty double nx\nproperty double ny\n"
         "property double nz\nproperty ushort intensity\nend_header\n";
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    ply << pts[i].first.x() << " " << pts[i].first.y() << " " << pts[i].first.z() << " " << pts[i].second.x() << " "
        << pts[i].second.y() << " " << pts[i].second.z() << " " << i % 65536 << "\n";
    if(i == 1000)
      ply << "40 40 40 0 0 1 7\n";
    if(i == 2000)
      ply << "1 1 0.1 0 0 0 8\n";
    if(i == 3000)
      ply << "nan 1 0.1 0 0 1 9\n";
  }
  write_text(file("big.ply"), ply.str());
  // 6003 points of about 366 bytes (one attribute): 2.2 MB in memory; 300K: tiles
  const std::string in = q(file("big.ply"));
  struct Case
  {
    std::string options, output;
  };
  const Case cases[] = {
    {"--radius 0.12 --color mean", "r.ply"},  // robust ASO, sample weights
    {"--radius 0.12 --method apss --ascii", "apss.ply"},
    {"--neighbors 30 --variant paper --fields mean,k_min,valid --float", "k.ply"},
    {"--neighbors 30 --color gaussian", "kw.ply"},  // robust ASO by count
    {"--neighbors 20 --method apss --color k_max", "k.csv"},
  };
  for(const Case& c : cases)
  {
    INFO(c.options);
    const Run memory = run_tool(in + " " + q(file("memory_" + c.output)) + " " + c.options);
    REQUIRE(memory.status == 0);
    CHECK(memory.out.find("  tiles") == std::string::npos);
    const Run tiled = run_tool(in + " " + q(file("tiled_" + c.output)) + " " + c.options + " --memory-limit 300K");
    REQUIRE(tiled.status == 0);
    INFO(tiled.out);
    // several tiles, each with fewer points than the cloud
    std::size_t tiles = 0, largest = 0;
    const std::size_t at = tiled.out.find("  tiles       ");
    REQUIRE(at != std::string::npos);
    std::istringstream(tiled.out.substr(at + 14)) >> tiles;
    const std::size_t most = tiled.out.find("at most ", at);
    REQUIRE(most != std::string::npos);
    std::istringstream(tiled.out.substr(most + 8)) >> largest;
    CHECK(tiles >= 4);
    // by count, the far point's tile reaches its 30 nearest: most of the cloud
    if(c.options.find("--radius") != std::string::npos)
      CHECK(largest < pts.size() / 2);
    const std::string a = read_text(file("memory_" + c.output)), b = read_text(file("tiled_" + c.output));
    CHECK(a.size() > 6000 * 30);
    CHECK(a == b);
    // the same report: counts of valid and invalid points, neighbours, H and K
    auto report = [](const std::string& out) {
      const std::size_t v = out.find("  valid"), t = out.find("  time"), h = out.find("  H (mean)");
      return out.substr(v, t - v) + out.substr(h);
    };
    CHECK(report(memory.out) == report(tiled.out));
  }
  // the invalid rows are there, in place: the far point, the zero normal, the NaN
  {
    const std::string csv = read_text(file("tiled_k.csv"));
    std::istringstream lines(csv);
    std::string line;
    std::vector<std::string> rows;
    while(std::getline(lines, line))
      rows.push_back(line);
    REQUIRE(rows.size() == pts.size() + 4);
    auto ends_with = [](const std::string& s, const std::string& end) {
      return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
    };
    CHECK(rows[1002].rfind("40,40,40,", 0) == 0);
    CHECK(ends_with(rows[1002], ",7"));  // intensity
    // neighbors 0, valid 0, grey, the intensity
    CHECK(rows[2003].rfind("1,1,0.10000000000000001,nan,", 0) == 0);
    CHECK(ends_with(rows[2003], ",0,0,128,128,128,8"));
    CHECK(rows[3004].rfind("nan,1,", 0) == 0);
    CHECK(ends_with(rows[3004], ",0,0,128,128,128,9"));
  }
  // no temporary file is left
  CHECK(files_starting_with(".tiled_") == 0);

  // without normals, a first pass of tiles estimates them (here with a local orientation)
  write_xyz(file("no_normals.xyz"), pts, false);
  for(const std::string scale : {"--radius 0.12", "--neighbors 30"})
  {
    INFO(scale);
    const std::string options = " " + scale + " --orient +z --normal-neighbors 12 --fields normal,mean,valid";
    const Run memory = run_tool(q(file("no_normals.xyz")) + " " + q(file("nn_memory.ply")) + options);
    const Run tiled =
      run_tool(q(file("no_normals.xyz")) + " " + q(file("nn_tiled.ply")) + options + " --memory-limit 300K");
    REQUIRE(memory.status == 0);
    REQUIRE(tiled.status == 0);
    CHECK(tiled.out.find("  tiles") != std::string::npos);
    CHECK(tiled.out.find("(normals estimated)") != std::string::npos);
    CHECK(tiled.err.find("has no normals: estimating them") != std::string::npos);
    const std::string a = read_text(file("nn_memory.ply")), b = read_text(file("nn_tiled.ply"));
    CHECK(a.size() > 6000 * 40);
    CHECK(a == b);
  }

  // the default orientation (a spanning tree over the whole cloud) and the default scale: the
  // normals estimated in tiles first, oriented over the whole cloud, then the curvature tiles
  // (6000 points: 3.0 MB in memory with the automatic scale, 2.5 MB for the gathered normals)
  {
    const std::string options = " --normal-neighbors 12 --fields normal,mean,valid,neighbors";
    const Run memory = run_tool(q(file("no_normals.xyz")) + " " + q(file("mst_memory.ply")) + options);
    const Run tiled =
      run_tool(q(file("no_normals.xyz")) + " " + q(file("mst_tiled.ply")) + options + " --memory-limit 2900K");
    REQUIRE(memory.status == 0);
    REQUIRE(tiled.status == 0);
    INFO(tiled.out);
    CHECK(memory.out.find("  tiles") == std::string::npos);
    CHECK(tiled.out.find("oriented over the whole cloud in memory") != std::string::npos);
    CHECK(tiled.out.find("oriented mst: along a minimum spanning tree") != std::string::npos);
    const std::string a = read_text(file("mst_memory.ply")), b = read_text(file("mst_tiled.ply"));
    CHECK(a.size() > 6000 * 40);
    CHECK(a == b);
  }

  // what cannot be tiled is refused with the reason and what to do
  {
    const Run r = run_tool(q(file("no_normals.xyz")) + " " + q(file("x.ply")) + " --radius 0.12 --memory-limit 300K");
    CHECK(r.status == 2);
    CHECK(r.err.find("orienting them along a spanning tree over the whole cloud (--orient auto here) needs "
                     "--memory-limit 2.") != std::string::npos);
    CHECK(r.err.find("or orient them locally, tile by tile: --orient +z") != std::string::npos);
    const Run s = run_tool(in + " " + q(file("x.ply")) + " --radius 3x --memory-limit 300K");
    CHECK(s.status == 2);
    CHECK(s.err.find("--radius 3x needs the whole cloud") != std::string::npos);
    const Run u = run_tool(in + " " + q(file("x.ply")) + " --memory-limit 12Q");
    CHECK(u.status == 2);
    CHECK(u.err.find("--memory-limit expects a positive size") != std::string::npos);
    CHECK(files_starting_with("x.ply") == 0);
  }
}

// ---------------------------------------------------------------------------------------
// Tiles under adversarial input, VCM reproducible, signals in every phase (issue 30)

namespace {

// run_tool() under `timeout`: a run that hangs fails (status 124 or 137) instead of holding
// up the suite; `env` is put before the command (NAME=value ...).
Run run_tool_within(int seconds, const std::string& args, const std::string& env = "")
{
  return run_tool_after(env + " timeout -k 5 " + std::to_string(seconds) + " ", args);
}

// Runs `input` whole, then in tiles at each memory limit: the same exit status (0, or 3 when
// no point is valid) and the same output bytes, and the tiled runs in tiles indeed. Returns
// the whole run's output.
std::string same_whole_and_tiled(const std::string& input, const std::string& options,
                                 const std::vector<std::string>& limits, const std::string& extension = ".ply",
                                 int status = 0)
{
  const std::string whole_output = file("whole" + extension);
  const Run whole = run_tool_within(120, q(input) + " " + q(whole_output) + " " + options);
  INFO(options << "\n" << whole.err);
  REQUIRE(whole.status == status);
  CHECK(whole.out.find("  tiles") == std::string::npos);
  const std::string expected = read_text(whole_output);
  for(const std::string& limit : limits)
  {
    INFO("--memory-limit " << limit);
    const std::string tiled_output = file("tiled" + extension);
    fs::remove(tiled_output);
    const Run tiled =
      run_tool_within(120, q(input) + " " + q(tiled_output) + " " + options + " --memory-limit " + limit);
    INFO(tiled.err);
    CHECK(tiled.status == status);
    CHECK(tiled.out.find("  tiles") != std::string::npos);
    CHECK(read_text(tiled_output) == expected);
  }
  return expected;
}

}  // namespace

// Two real airborne tiles without normals (data/real, PDAL's test data): the default pipeline
// orients them upwards because they are 2.5-D, gives every ground normal up and a valid estimate
// on vegetation with a lower normal coherence, and vegetation rougher than ground. Measured
// (2026-11-27): ground up 100% on both, vegetation valid 100%, median |H| vegetation / ground
// 8.76 (sample_c) and 2.23 (warsaw_small), median coherence ground 0.999 and 0.996, vegetation
// 0.93 and 0.85-0.99.
TEST_CASE("tool: real airborne tiles without normals, ground up, vegetation valid, vegetation rougher than ground")
{
  for(const std::string name : {"sample_c", "warsaw_small"})
  {
    const std::string out = file(name + "_default.csv");
    const Run r = run_tool(q(repo_data("real/" + name + ".las")) + " " + q(out));
    INFO(name << ": " << r.err);
    REQUIRE(r.status == 0);
    CHECK(r.err.find("oriented +z (LAS file, 2.5-D") != std::string::npos);
    const std::string csv = read_text(out);
    {
      // The "normals" line's shares are those of the estimated normals; the output holds the
      // ASO's corrected normals, which turn a few of them (vegetation: measured 0 on sample_c
      // and 57 of 2560 near-vertical ones on warsaw_small), and the "output" line states those.
      const std::vector<std::string> nx = csv_column(csv, "nx"), ny = csv_column(csv, "ny"),
                                     nzs = csv_column(csv, "nz");
      std::size_t usable = 0, vertical = 0, up = 0;
      for(std::size_t i = 0; i < nx.size(); ++i)
      {
        const double v[3] = {std::stod(nx[i]), std::stod(ny[i]), std::stod(nzs[i])};
        if(!std::isfinite(v[0]) || v[0] * v[0] + v[1] * v[1] + v[2] * v[2] == 0)
          continue;
        ++usable;
        if(PSC::is_near_vertical(v[0], v[1], v[2]))
        {
          ++vertical;
          up += v[2] > 0 ? 1 : 0;
        }
      }
      REQUIRE(usable > 1000);
      const std::string claim = "% of the estimated normals within 60 degrees of the vertical; 100% of those point up";
      const std::size_t at = r.err.find(claim);
      REQUIRE(at != std::string::npos);
      const std::size_t from = r.err.rfind(' ', at) + 1;
      const double claimed = std::stod(r.err.substr(from, at - from));
      CHECK(std::abs(claimed - 100.0 * double(vertical) / double(usable)) < 1.0);
      CHECK(double(up) >= 0.97 * double(vertical));
      // the output line: the output's own shares, to 0.1%, and its count of normals down exactly
      const std::string output_claim = "% of the valid rows' normals within 60 degrees of the vertical, ";
      const std::size_t o = r.out.find(output_claim);
      REQUIRE(o != std::string::npos);
      const std::size_t o_from = r.out.rfind(' ', o) + 1;
      CHECK(std::abs(std::stod(r.out.substr(o_from, o - o_from)) - 100.0 * double(vertical) / double(usable)) <= 0.051);
      const std::size_t u = o + output_claim.size();
      CHECK(std::abs(std::stod(r.out.substr(u)) - 100.0 * double(up) / double(vertical)) <= 0.051);
      const std::size_t d = r.out.find("point up (", u);
      REQUIRE(d != std::string::npos);
      CHECK(std::stoul(r.out.substr(d + 10)) == vertical - up);
    }
    const std::vector<std::string> cls = csv_column(csv, "classification"), nz = csv_column(csv, "nz"),
                                   valid = csv_column(csv, "valid"), mean = csv_column(csv, "mean"),
                                   coherence = csv_column(csv, "normal_coherence");
    REQUIRE(cls.size() > 1000);
    std::size_t ground = 0, ground_up = 0, vegetation = 0, vegetation_valid = 0;
    std::vector<double> ground_h, vegetation_h, ground_c, vegetation_c;
    for(std::size_t i = 0; i < cls.size(); ++i)
    {
      const int c = std::stoi(cls[i]) & 31;
      const bool ok = valid[i] == "1";
      if(c == 2)
      {
        ++ground;
        ground_up += std::stod(nz[i]) > 0;
        if(ok)
        {
          ground_h.push_back(std::abs(std::stod(mean[i])));
          ground_c.push_back(std::stod(coherence[i]));
        }
      }
      else if(c >= 3 && c <= 5)
      {
        ++vegetation;
        vegetation_valid += ok;
        if(ok)
        {
          vegetation_h.push_back(std::abs(std::stod(mean[i])));
          vegetation_c.push_back(std::stod(coherence[i]));
        }
      }
    }
    const auto median = [](std::vector<double> v) {
      std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
      return v[v.size() / 2];
    };
    REQUIRE(ground > 1000);
    REQUIRE(vegetation > 100);
    CHECK(double(ground_up) >= 0.99 * double(ground));
    CHECK(double(vegetation_valid) >= 0.95 * double(vegetation));
    REQUIRE(ground_h.size() > 1000);
    CHECK(median(vegetation_h) > 1.5 * median(ground_h));
    CHECK(median(ground_c) > 0.98);
    CHECK(median(vegetation_c) < median(ground_c));
  }
}

// Issue 42, item 2: the default on a real LAS file larger than the memory limit, without
// normals. --orient auto makes it 2.5-D (a spanning tree over the whole cloud, with its
// near-vertical normals up): the normals are estimated in tiles first and oriented over the
// whole cloud, bitwise as in memory (sample_c: 22 curvature tiles after 4 tiles of normals at
// 8M; warsaw_small in one tile of each).
TEST_CASE("tool: the default tiles a real LAS file without normals, bitwise as in memory")
{
  same_whole_and_tiled(repo_data("real/sample_c.las"), "", {"8M"}, ".csv");
  same_whole_and_tiled(repo_data("real/warsaw_small.las"), "--fields mean,normal,valid", {"1500K"}, ".csv");
}

// Class 1 of issue 30: the tiles' halo retry when the cloud has fewer points than a
// neighbourhood asks for. The whole run gives every point all the others; the tiled run
// failed with "internal error: the tile's halo inf is too small ...; a halo of inf suffices"
// (exit 1), or with a finite halo said too small and sufficient at once.
TEST_CASE("tool: tiles of clouds smaller than a neighbourhood give the whole run's bytes (3 and 39 points, 60 LAS "
          "points with normals from 200 neighbours, pairs on a line)")
{
  for(std::size_t n : {std::size_t(3), std::size_t(39)})
  {
    INFO(n << " points with normals, the default scale");
    write_xyz(file("few.xyz"), sphere(n, 1.0));
    // (3 points: no valid estimate, exit status 3 in both runs)
    const std::string csv =
      same_whole_and_tiled(file("few.xyz"), "--fields mean,neighbors,valid", {"100", "500"}, ".csv", n == 3 ? 3 : 0);
    // every point has every point as neighbour; 3 are too few (too_few_neighbors), 39 enough
    const std::vector<std::string> neighbors = csv_column(csv, "neighbors"), valid = csv_column(csv, "valid");
    REQUIRE(neighbors.size() == n);
    CHECK(std::count(neighbors.begin(), neighbors.end(), std::to_string(n)) == std::ptrdiff_t(n));
    CHECK(std::count(valid.begin(), valid.end(), n == 3 ? "0" : "1") == std::ptrdiff_t(n));
  }
  {
    INFO("60 LAS points without normals, --orient scanner --normal-neighbors 200");
    const double offset[3] = {0, 0, 0}, scanner[3] = {0, 0, 0};
    write_las(file("few.las"), sphere(60, 1.0), 4, 3, 0.001, offset, 0, scanner);
    const std::string csv = same_whole_and_tiled(
      file("few.las"), "--orient scanner --normal-neighbors 200 --drop-attributes", {"1K", "4K"}, ".csv");
    // (every normal is the fit of the whole sphere: meaningless, but the same) 40 neighbours
    const std::vector<std::string> neighbors = csv_column(csv, "neighbors");
    REQUIRE(neighbors.size() == 60);
    CHECK(std::count(neighbors.begin(), neighbors.end(), "40") == 60);
  }
  {
    // pairs of coincident points 2 apart on a line: a tile (halo 2r = 0.6 and a normal halo
    // of 1e-150 guessed from the line's zero area) holds one pair, fewer than the normals' 18
    // neighbours, of extent 0; the normals asked for 2e-150 more, which rounded away in
    // 0.6 + 2e-150: "the tile's halo 0.59999999999999998 is too small for exact results; a
    // halo of 0.59999999999999998 suffices". Collinear: no normal in either run.
    INFO("pairs on a line without normals, jets --radius 0.3 --orient +z");
    std::vector<Oriented_point> line;
    for(int i = 0; i < 24; ++i)
      line.emplace_back(Point(2.0 * (i / 2), 0, 0), Vector(0, 0, 1));
    const double offset[3] = {0, 0, 0};
    write_las(file("line.las"), line, 0, 2, 0.001, offset);
    const std::string csv = same_whole_and_tiled(
      file("line.las"), "--method jet --radius 0.3 --orient +z --drop-attributes", {"1K", "2K"}, ".csv", 3);
    const std::vector<std::string> valid = csv_column(csv, "valid");
    CHECK(std::count(valid.begin(), valid.end(), "0") == 24);
  }
}

// Class 2 of issue 30: coordinates whose extent overflows a double. The tiled run hung (the
// tile grid's side stayed infinite; SIGTERM did not end it); now it tiles with arithmetic
// that cannot overflow and gives the whole run's bytes.
TEST_CASE("tool: clouds whose extent overflows a double are tiled as the whole run (points at -1e308 and 1e308 in .xyz "
          ".ply .off, a LAS X scale of 1.5e304)")
{
  std::vector<Oriented_point> pts = sphere(80, 1.0);
  pts.insert(pts.begin() + 30, Oriented_point(Point(-1e308, 0, 0), Vector(0, 0, 1)));
  pts.emplace_back(Point(1e308, 0, 0), Vector(0, 0, 1));
  write_xyz(file("overflow.xyz"), pts);
  // the same points in ASCII PLY and OFF
  {
    std::ostringstream ply, off;
    ply.precision(17);
    off.precision(17);
    ply << "ply\nformat ascii 1.0\nelement vertex " << pts.size()
        << "\nproperty double x\nproperty double y\nproperty double z\nproperty double nx\nproperty double ny\n"
           "property double nz\nend_header\n";
    off << "NOFF\n" << pts.size() << " 0 0\n";
    for(const Oriented_point& p : pts)
    {
      ply << p.first << " " << p.second << "\n";
      off << p.first << " " << p.second << "\n";
    }
    write_text(file("overflow.ply"), ply.str());
    write_text(file("overflow.off"), off.str());
  }
  const std::pair<std::string, std::string> cases[] = {
    {"overflow.xyz", "--method aso"}, {"overflow.ply", "--method apss"}, {"overflow.off", "--method wavejet"}};
  for(const auto& c : cases)
  {
    INFO(c.first << " " << c.second);
    const std::string csv =
      same_whole_and_tiled(file(c.first), c.second + " --fields mean,neighbors,valid", {"2K", "8K"}, ".csv");
    // the sphere's points valid, the two far points not (degenerate_fit); 40 neighbours each
    const std::vector<std::string> valid = csv_column(csv, "valid"), neighbors = csv_column(csv, "neighbors"),
                                   mean = csv_column(csv, "mean");
    REQUIRE(valid.size() == 82);
    CHECK(std::count(valid.begin(), valid.end(), "1") == 80);
    CHECK(valid[30] == "0");
    CHECK(valid[81] == "0");
    CHECK(std::count(neighbors.begin(), neighbors.end(), "40") == 82);
    if(c.second != "--method wavejet")  // (wavejets fit a half sphere poorly: H 1.77 to 1.88)
    {
      std::size_t near_one = 0;
      for(const std::string& h : mean)
        near_one += std::abs(std::atof(h.c_str()) - 1) < 0.01;
      CHECK(near_one == 80);
    }
  }
  {
    // a LAS file whose X scale, 1.5e304, is finite (the reader accepts it): x from -1.5e308
    // to 1.5e308, so far apart that no normal is defined (collinear neighbourhoods)
    INFO("LAS X scale 1.5e304");
    const double offset[3] = {0, 0, 0};
    write_las(file("xscale.las"), sphere(80, 10.0), 0, 2, 0.001, offset);
    std::string las = read_text(file("xscale.las"));
    put_le<double>(las, 131, 1.5e304);
    write_text(file("xscale.las"), las);
    // (no valid estimate: exit status 3 in both runs)
    const std::string csv =
      same_whole_and_tiled(file("xscale.las"), "--orient +z --drop-attributes --fields mean,valid", {"2K"}, ".csv", 3);
    const std::vector<std::string> x = csv_column(csv, "x"), valid = csv_column(csv, "valid");
    REQUIRE(x.size() == 80);
    const auto [lo, hi] = std::minmax_element(x.begin(), x.end(), [](const std::string& a, const std::string& b) {
      return std::atof(a.c_str()) < std::atof(b.c_str());
    });
    CHECK(std::atof(hi->c_str()) - std::atof(lo->c_str()) == HUGE_VAL);  // the extent overflows
    CHECK(std::count(valid.begin(), valid.end(), "0") == 80);
  }
}

// Class 3 of issue 30: VCM depended on memory addresses (CGAL's convex hull orders the edges
// of its visible sets by vertex address): two runs with --threads 1 differed in the last bits
// in 78 of 80 rows, one result of three at random. Its cells are now computed from data
// alone: every run, sequential or parallel, gives the same bytes. VCM's tiles stay refused.
TEST_CASE("tool: VCM gives the same bytes in every run, sequential and parallel, by radius and by count, and tiled VCM "
          "is refused")
{
  write_xyz(file("vcm.xyz"), sphere(80, 1.0));
  for(const std::string scale : {"--radius 1.2", "--neighbors 20"})
  {
    INFO(scale);
    std::string first;
    for(int run = 0; run < 8; ++run)
    {
      const std::string options = " --method vcm " + scale + (run % 2 ? " --threads 1" : "");
      const Run r = run_tool_within(60, q(file("vcm.xyz")) + " " + q(file("vcm.ply")) + options);
      REQUIRE(r.status == 0);
      const std::string bytes = read_text(file("vcm.ply"));
      if(run == 0)
      {
        first = bytes;
        // valid estimates (not a reproducible run of NaN)
        CHECK(r.out.find("valid       80 (100.00 %)") != std::string::npos);
      }
      INFO("run " << run);
      CHECK(bytes == first);
    }
  }
  const Run tiled =
    run_tool_within(60, q(file("vcm.xyz")) + " " + q(file("vcm.ply")) + " --method vcm --memory-limit 2K");
  CHECK(tiled.status == 2);
  CHECK(std::count(tiled.err.begin(), tiled.err.end(), '\n') == 1);
  CHECK(tiled.err.find("--method vcm needs the whole cloud") != std::string::npos);
}

// Issue 30: SIGINT and SIGTERM stop every phase of a tiled run at its next progress report
// (about 1% of its work or 0.25 s). The tool's test hook PSC_TOOL_TEST_SIGNAL=SIG@PHASE raises
// the signal as the phase begins (PHASE: the start of its name, '*' standing for any text);
// the run must exit 130 (SIGINT) or 143 (SIGTERM) naming that phase (a phase that went on
// would let the next one stop instead), leaving no output and no temporary file.
TEST_CASE("tool: SIGINT and SIGTERM stop every phase of a tiled run, with and without normals")
{
  write_xyz(file("phases.xyz"), sphere(1000, 1.0));
  write_xyz(file("phases_nn.xyz"), sphere(1000, 1.0), false);
  struct Case
  {
    std::string input, options, phase;
  };
  // (1000 points of about 300 bytes: 60K gives 56 to 345 tiles with normals, 250K 8 without;
  // fixed counts: the automatic scale's halo of 640 neighbours would cover this small sphere)
  const Case cases[] = {
    {"phases.xyz", "--memory-limit 60K --neighbors 40", "reading"},
    {"phases.xyz", "--memory-limit 60K --neighbors 40", "density"},
    {"phases.xyz", "--memory-limit 60K --neighbors 40", "tile *read"},
    {"phases.xyz", "--memory-limit 60K --neighbors 40", "tile *curvatures"},
    {"phases.xyz", "--memory-limit 60K --neighbors 30", "tile *read#9"},  // a halo grown: tiles read again
    {"phases.xyz", "--memory-limit 60K --neighbors 30", "tile *curvatures#9"},
    {"phases.xyz", "--memory-limit 60K --radius 0.25", "tile *curvatures#20"},
    {"phases.xyz", "--memory-limit 60K --radius 0.25", "writing"},
    {"phases_nn.xyz", "--memory-limit 250K --orient +z --neighbors 40",
     "tile *curvatures#3"},  // the normals, then the curvatures
    {"phases_nn.xyz", "--memory-limit 250K --orient +z --radius 0.25", "writing"},
  };
  for(const Case& c : cases)
    for(const std::string signal : {"INT", "TERM"})
    {
      INFO(c.input << " " << c.options << ", SIG" << signal << " as phase '" << c.phase << "' begins");
      fs::remove(file("phases.ply"));
      const Run r = run_tool_within(120, q(file(c.input)) + " " + q(file("phases.ply")) + " " + c.options,
                                    "PSC_TOOL_TEST_SIGNAL='" + signal + "@" + c.phase + "'");
      INFO(r.err);
      CHECK(r.status == (signal == "TERM" ? 143 : 130));  // 128 + the signal, as a shell reports it
      // "interrupted (tile 9/23 curvatures), nothing written"
      const std::string name = c.phase.substr(0, c.phase.find('#'));
      const std::size_t star = name.find('*');
      const std::string head = name.substr(0, star), tail = star == std::string::npos ? "" : name.substr(star + 1);
      const std::size_t at = r.err.find("interrupted (" + head);
      CHECK(at != std::string::npos);
      CHECK(r.err.find(tail + "), nothing written", at) != std::string::npos);
      CHECK(!fs::exists(file("phases.ply")));
      CHECK(files_starting_with(".phases.ply") == 0);
    }
  // undisturbed, the same runs are tiled and succeed
  for(const std::string input : {"phases.xyz --memory-limit 60K", "phases_nn.xyz --memory-limit 250K --orient +z"})
  {
    const Run r = run_tool_within(120, q(file(input.substr(0, input.find(' ')))) + " " + q(file("phases.ply")) +
                                         input.substr(input.find(' ')));
    CHECK(r.status == 0);
    CHECK(r.out.find("  tiles") != std::string::npos);
  }
}

// A real SIGTERM during a long tiled run (every point every point's neighbour) stops it.
TEST_CASE("tool: SIGTERM during a long tiled run exits 143 and leaves no file")
{
  write_xyz(file("long.xyz"), sphere(20000, 1.0));
  fs::remove(file("long.ply"));
  // (\$: expanded by bash -c, not by the shell of std::system; the watchdog, its output away
  // from the test's, only keeps a run that ignored the signal from holding up the suite)
  const std::string script = std::string("'") + PSC_TOOL_PATH + "' '" + file("long.xyz") + "' '" + file("long.ply") +
                             "' --radius 3 --memory-limit 2M --quiet 2> '" + file("long.err") +
                             "' & pid=\\$!; (sleep 300; kill -KILL \\$pid) > /dev/null 2>&1 & dog=\\$!; sleep 1; "
                             "kill -TERM \\$pid; wait \\$pid; echo \\$? > '" +
                             file("long.status") + "'; kill \\$dog 2> /dev/null; true";
  REQUIRE(std::system(("bash -c \"" + script + "\"").c_str()) == 0);
  CHECK(std::atoi(read_text(file("long.status")).c_str()) == 143);
  CHECK(read_text(file("long.err")).find("interrupted (") != std::string::npos);
  CHECK(!fs::exists(file("long.ply")));
  CHECK(files_starting_with(".long.ply") == 0);
}

// Issue 28, item 12: the progress bar's line (drawn on a terminal only, redrawn twice a second
// by a timer even when a phase reports no progress): the elapsed time, and an ETA once a
// fraction of at least 1% is known and a second has passed.
// Issue 43, item 4: a pass over the tiles is one progress line whose fraction follows the time
// expected (tile_pass_progress.h), so that its ETA holds from the first tiles on.
TEST_CASE("tool: the fraction of a pass over the tiles follows the time the tiles take")
{
  double now = 0;
  // three tiles of 100 own points, one of 50; a read of the file took 1 s (the density pass)
  psc_tool::Tile_pass_progress pass({100, 100, 100, 50}, 1.0, [&now]() { return now; });
  const double prior = psc_tool::Tile_pass_progress::estimation_prior;
  pass.begin_read(0);
  CHECK(pass.at(0.0) == Approx(0.0));
  now = 0.5;  // half the first read in 0.5 s: nothing measured yet, 4 reads and estimations to go
  CHECK(pass.at(0.5) == Approx(0.5 / (0.5 + 0.5 * 1 + prior + 3 * 1)));  // (the estimations: `prior` reads in all)
  now = 1;
  pass.begin_estimation(0);
  now = 1.5;                                     // its first report after 0.5 s of set-up
  CHECK(pass.at(0.0) >= 0.5 / (1 + prior + 3));  // (never less than reported)
  now = 5.5;  // a tenth in 4 s: 40 s the whole from its first report, 40.5 s the tile's estimation
  pass.at(0.1);
  now = 9.5;
  CHECK(pass.at(0.2) == Approx(9.5 / (9.5 + 0.8 * 40 + 3 * 1 + (40.5 / 100) * 250)));
  now = 41.5;
  CHECK(pass.at(1.0) == Approx(41.5 / (41.5 + 3 * 1 + 0.405 * 250)));
  pass.end_tile();
  // from the first tile done on: 1 s a read, 0.405 s a point
  now = 42;
  pass.begin_read(1);
  CHECK(pass.at(0.0) == Approx(42 / (42 + 1 + 40.5 + 2 * 1 + 0.405 * 150)));
  // a tile read again (its halo grew): its refused try is time the pass took, never a step back;
  // the reads are those of the tiles done (not the current one's as well)
  now = 43;
  pass.begin_estimation(1);
  const double before = pass.at(0.0);
  CHECK(before == Approx(43 / (43 + 40.5 + 2 * 1 + 0.405 * 150)));
  now = 50;
  pass.begin_read(1);
  CHECK(pass.at(0.0) >= before);
  now = 51;
  pass.begin_estimation(1);
  pass.at(0.0);
  now = 91.5;
  CHECK(pass.at(1.0) < 1.0);  // (the others to come)
  pass.end_tile();
  now = 92;
  pass.begin_read(2);
  CHECK(pass.at(0.0) < 1.0);
  // no tile: the whole pass at once
  psc_tool::Tile_pass_progress empty({}, 1.0, [&now]() { return now; });
  CHECK(empty.at(1.0) == 1.0);
}

TEST_CASE("tool: the progress line shows the elapsed time, an ETA once a fraction is known, at one width")
{
  using psc_tool::progress_line;
  const std::string frozen = progress_line("curvatures", 0.0, 14.2);  // no progress yet: the time still moves
  CHECK(frozen.find("  0%") != std::string::npos);
  CHECK(frozen.find("14.2 s") != std::string::npos);
  CHECK(frozen.find("ETA") == std::string::npos);
  CHECK(progress_line("curvatures", 0.25, 10.0).find(" 25%") != std::string::npos);
  CHECK(progress_line("curvatures", 0.25, 10.0).find("ETA 30 s") != std::string::npos);
  CHECK(progress_line("curvatures", 0.5, 150.0).find("ETA 2 min 30 s") != std::string::npos);
  CHECK(progress_line("curvatures", 0.01, 100.0).find("ETA 2 h 45 min") != std::string::npos);  // 9900 s
  CHECK(progress_line("curvatures", 0.5, 0.5).find("ETA") == std::string::npos);   // under a second: no guess
  CHECK(progress_line("curvatures", 1.0, 20.0).find("ETA") == std::string::npos);  // done
  CHECK(progress_line("curvatures", std::nan(""), 3.0).find("  0%") != std::string::npos);
  CHECK(psc_tool::eta_text(59.6) == "1 min 00 s");
  // drawn over each other after '\r': one width, or a shorter line would leave a tail
  for(const auto& fs : {std::make_pair(0.0, 0.0), std::make_pair(0.5, 150.0), std::make_pair(0.01, 100.0),
                        std::make_pair(1.0, 20.0), std::make_pair(0.999, 5e4)})
    CHECK(progress_line("curvatures", fs.first, fs.second).size() == frozen.size());
  // a pass over the tiles: its step after the line, padded to the phase's longest
  const std::string step = progress_line("curvatures", 0.5, 150.0, "tile 3/12 read", 20);
  CHECK(step.size() == frozen.size() - 10 + 21);
  CHECK(step.find("ETA 2 min 30 s") != std::string::npos);
  CHECK(step.find(" tile 3/12 read      ") == frozen.size() - 10);
  CHECK(progress_line("curvatures", 0.5, 150.0, "tile 3/9 curvatures", 19).size() <= 88);

  // not on a terminal (stderr is a file here): no bar, no '\r', as before
  write_xyz(file("bar.xyz"), sphere(500, 1.0));
  const Run r = run_tool(q(file("bar.xyz")) + " " + q(file("bar.ply")) + " --radius 0.3");
  REQUIRE(r.status == 0);
  CHECK(r.err.find('\r') == std::string::npos);
  CHECK(r.err.find("ETA") == std::string::npos);
}

// Issue 28, item 13: a run killed (SIGKILL) while it computes leaves no file: the output's
// temporary file is created when writing starts (the space reserved before is held by a file
// unlinked at once). One killed while writing leaves ".OUTPUT.tmp-PID-XXXXXX", which the next
// run writing OUTPUT removes, with a note, as it does those of earlier versions
// (".OUTPUT.tmp-XXXXXX"), never those of a run still going (its PID alive).
TEST_CASE(
  "tool: a run killed while computing leaves no temporary file, and the next run removes a killed run's with a note")
{
  write_xyz(file("killed.xyz"), sphere(2000, 1.0));
  write_xyz(file("killed_nn.xyz"), sphere(2000, 1.0), false);
  const struct
  {
    std::string input, options, phase;
  } cases[] = {{"killed.xyz", "--radius 0.3", "curvatures"},
               {"killed.xyz", "--radius 0.3x", "spacing"},
               {"killed_nn.xyz", "--radius 0.3", "normals"},
               {"killed.xyz", "--radius 0.3 --memory-limit 100K", "tile *curvatures#2"},
               {"killed_nn.xyz", "--radius 0.3 --memory-limit 300K --orient +z --ascii", "tile *curvatures#2"},
               {"killed.xyz", "--radius 0.3 --memory-limit 100K", "tile *read#3"}};
  for(const auto& c : cases)
  {
    INFO(c.input << " " << c.options << ", SIGKILL as phase '" << c.phase << "' begins");
    const Run r = run_tool_within(60, q(file(c.input)) + " " + q(file("killed.ply")) + " " + c.options,
                                  "PSC_TOOL_TEST_SIGNAL='KILL@" + c.phase + "'");
    CHECK(r.status == 137);  // killed (timeout reports 128 + SIGKILL)
    CHECK(!fs::exists(file("killed.ply")));
    CHECK(files_starting_with(".killed.ply") == 0);
  }

  // killed while writing: the partial temporary file stays, and the next run removes it
  const Run w = run_tool_within(60, q(file("killed.xyz")) + " " + q(file("killed.ply")) + " --radius 0.3",
                                "PSC_TOOL_TEST_SIGNAL='KILL@writing'");
  CHECK(w.status == 137);
  CHECK(files_starting_with(".killed.ply.tmp-") == 1);
  // planted: a run of an earlier version, and killed ones (a PID above Linux's largest)
  for(const std::string name :
      {".killed.ply.tmp-AbC123", ".killed.ply.tmp-4194305-xYz789", ".killed.ply.tmp-4194305-tile3-aBcDeF"})
    write_text(file(name), "partial");
  // kept: a run still going (this process), other names
  const std::string running = ".killed.ply.tmp-" + std::to_string(::getpid()) + "-kEePmE";
  for(const std::string& name : {running, std::string(".killed.ply.tmp-notes.txt"),
                                 std::string(".other.ply.tmp-AbC123"), std::string("killed.ply.tmp-AbC123")})
    write_text(file(name), "keep");
  const Run next = run_tool(q(file("killed.xyz")) + " " + q(file("killed.ply")) + " --radius 0.3");
  INFO(next.err);
  REQUIRE(next.status == 0);
  CHECK(next.err.find("note: removed 4 temporary files of earlier runs writing") != std::string::npos);
  CHECK(std::count(next.err.begin(), next.err.end(), '\n') == 1);
  CHECK(files_starting_with(".killed.ply.tmp-") == 2);  // the running one and notes.txt
  CHECK(fs::exists(file(running)));
  CHECK(fs::exists(file(".killed.ply.tmp-notes.txt")));
  CHECK(fs::exists(file(".other.ply.tmp-AbC123")));
  CHECK(fs::exists(file("killed.ply.tmp-AbC123")));
  CHECK(fs::exists(file("killed.ply")));
  // nothing left to remove: no note
  const Run again = run_tool(q(file("killed.xyz")) + " " + q(file("killed.ply")) + " --radius 0.3");
  CHECK(again.status == 0);
  CHECK(again.err.find("note:") == std::string::npos);
  for(const std::string& name : {running, std::string(".killed.ply.tmp-notes.txt"),
                                 std::string(".other.ply.tmp-AbC123"), std::string("killed.ply.tmp-AbC123")})
    fs::remove(file(name));
}

// Issue 28, item 14: an OUTPUT that cannot be written is refused before the estimation (the
// SIGKILL hook at the estimation's start would kill a run that reached it), with one line:
// a directory, a folder that does not exist or is a file, more than the file size limit
// (ulimit -f: the reservation of the output's size fails with EFBIG); a full disk below.
TEST_CASE(
  "tool: an OUTPUT that is a directory, in a missing folder or over the file size limit fails before the estimation")
{
  write_xyz(file("early.xyz"), sphere(2000, 1.0));
  const std::string kill = "PSC_TOOL_TEST_SIGNAL='KILL@curvatures'";
  auto refused = [&](const std::string& output, const std::string& prefix, const std::string& message) {
    INFO(output << " " << prefix);
    const Run r = run_tool_within(60, q(file("early.xyz")) + " " + q(output) + " --radius 0.3", prefix + " " + kill);
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find(message) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(files_starting_with(".early") == 0);
  };
  fs::create_directories(file("dir.ply"));
  refused(file("dir.ply"), "", "is a directory: give a file name, such as");
  CHECK(fs::is_empty(file("dir.ply")));
  refused(file("missing/sub/out.ply"), "",
          "its folder '" + file("missing/sub") + "' does not exist (create it with mkdir -p");
  CHECK(!fs::exists(file("missing")));
  refused(file("early.xyz/out.ply"), "", "is not a directory; choose another OUTPUT");
  // 277 KB of binary PLY, 860 KB of CSV at most, over a limit of 64 blocks (32 or 64 KB)
  refused(file("early.ply"), "ulimit -f 64;",
          "more than the largest file allowed (the shell's file size limit, ulimit -f");
  refused(file("early.csv"), "ulimit -f 64;", "more than the largest file allowed");
  CHECK(!fs::exists(file("early.ply")));
  // within the limit: the reservation, larger than a CSV written, is cut to the bytes written
  for(const std::string ext : {".ply", ".csv"})
  {
    const Run free_run = run_tool(q(file("early.xyz")) + " " + q(file("early_free" + ext)) + " --radius 0.3");
    const Run limited =
      run_tool_within(60, q(file("early.xyz")) + " " + q(file("early" + ext)) + " --radius 0.3", "ulimit -f 100000;");
    REQUIRE(free_run.status == 0);
    REQUIRE(limited.status == 0);
    const std::string expected = read_text(file("early_free" + ext));
    CHECK(expected.size() > 100000);
    CHECK(read_text(file("early" + ext)) == expected);
  }
}

// A full disk: a 128 KB tmpfs in a user and mount namespace, where the system allows it
// (skipped visibly where it does not, as in some containers).
TEST_CASE("tool: an OUTPUT on a full disk fails before the estimation, naming the space it needs")
{
  fs::create_directories(file("tiny"));
  const std::string mount = "mount -t tmpfs -o size=128k tmpfs '" + file("tiny") + "'";
  if(std::system(("unshare -rm sh -c \"" + mount + "\" > /dev/null 2>&1").c_str()) != 0)
  {
    skip_test("no user namespace to mount a tiny file system in (unshare -rm refused)");
    return;
  }
  write_xyz(file("full.xyz"), sphere(2000, 1.0));
  const std::string kill = "PSC_TOOL_TEST_SIGNAL='KILL@curvatures'";
  const std::string script = mount + " && " + kill + " '" + PSC_TOOL_PATH + "' '" + file("full.xyz") + "' '" +
                             file("tiny/early.ply") + "' --radius 0.3 2> '" + file("tiny.err") + "'; echo \\$? > '" +
                             file("tiny.status") + "'; ls -a '" + file("tiny") + "' | wc -l > '" + file("tiny.files") +
                             "'";
  REQUIRE(std::system(("unshare -rm sh -c \"" + script + "\"").c_str()) == 0);
  const std::string err = read_text(file("tiny.err"));
  INFO(err);
  CHECK(std::atoi(read_text(file("tiny.status")).c_str()) == 2);
  CHECK(err.find("not enough space for output '" + file("tiny/early.ply") +
                 "': it needs up to 277.0 KB (binary PLY "
                 "of 2000 points, 19 fields), the file system holding it has 128.0 KB free") != std::string::npos);
  CHECK(std::count(err.begin(), err.end(), '\n') == 1);
  CHECK(std::atoi(read_text(file("tiny.files")).c_str()) == 2);  // . and ..: nothing left
}

// Issue 28, item 15: a --memory-limit so small that it makes hundreds of tiles (each read
// again from the input with its halo: 1K on 2025 points makes about 750) is warned of with a
// limit giving at most 100; one above the machine's RAM too.
TEST_CASE("tool: a --memory-limit making hundreds of tiles or above the RAM is warned of, with the limit to give")
{
  // (a fixed count: the automatic scale's halo of 640 neighbours would cover this small plane;
  // a plane, as smaller tiles keep lowering the most points a tile reads: on a sphere of 1000
  // points, where they soon stop, the tiles are fewer than 500)
  write_xyz(file("limits.xyz"), plane(45, 0.2));
  const Run tiny =
    run_tool_within(120, q(file("limits.xyz")) + " " + q(file("limits.ply")) + " --memory-limit 1K --neighbors 40");
  INFO(tiny.err);
  REQUIRE(tiny.status == 0);
  const std::size_t at = tiny.err.find("warning: --memory-limit 1.0 KB makes ");
  REQUIRE(at != std::string::npos);
  const std::size_t tiles = std::stoul(tiny.err.substr(at + 37));
  CHECK(tiles > 500);
  CHECK(tiny.out.find("  tiles       " + std::to_string(tiles) + " ") != std::string::npos);
  const std::size_t give = tiny.err.find("; --memory-limit ", at);
  REQUIRE(give != std::string::npos);
  const std::string suggested = tiny.err.substr(give + 17, tiny.err.find(' ', give + 17) - give - 17);
  const std::size_t most = std::stoul(tiny.err.substr(tiny.err.find(" gives at most ", give) + 15));
  CHECK(most <= 100);
  CHECK(std::count(tiny.err.begin(), tiny.err.end(), '\n') == 1);
  // the memory stays bounded however many tiles: one temporary file for all their rows, read
  // back through buffers within the limit (a file per tile held a 1 MB buffer each: 750 MB
  // here; 10 MB now). Not under the sanitizers (AddressSanitizer's quarantine keeps freed memory).
#ifndef PSC_TEST_MEMORY_SANITIZED
  const std::pair<int, long> peak =
    run_tool_peak_kb(q(file("limits.xyz")) + " " + q(file("peak.ply")) + " --memory-limit 1K --neighbors 40");
  CHECK(peak.first == 0);
  CHECK(peak.second < 150 * 1024);
#endif
  // the limit suggested gives at most that many tiles, the same bytes, and no warning
  const std::string expected = read_text(file("limits.ply"));
  const Run fewer = run_tool_within(120, q(file("limits.xyz")) + " " + q(file("limits.ply")) +
                                           " --neighbors 40 --memory-limit " + suggested);
  INFO(suggested << "\n" << fewer.out);
  REQUIRE(fewer.status == 0);
  CHECK(fewer.err.empty());
  const std::size_t t = fewer.out.find("  tiles       ");
  REQUIRE(t != std::string::npos);
  CHECK(std::stoul(fewer.out.substr(t + 14)) <= most);
  CHECK(std::stoul(fewer.out.substr(t + 14)) > 1);
  CHECK(read_text(file("limits.ply")) == expected);

  // above the RAM
  const double ram = double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGE_SIZE));
  char ram_text[64];
  std::snprintf(ram_text, sizeof ram_text, "%.1f GB of RAM", ram / (1024.0 * 1024 * 1024));
  const Run huge =
    run_tool(q(file("limits.xyz")) + " " + q(file("limits.ply")) + " --memory-limit 1024T --neighbors 40");
  INFO(huge.err);
  CHECK(huge.status == 0);
  CHECK(huge.err.find("warning: --memory-limit 1024.0 TB exceeds this machine's memory (" + std::string(ram_text) +
                      "): ") != std::string::npos);
  CHECK(std::count(huge.err.begin(), huge.err.end(), '\n') == 1);
  // within it: silent
  const Run within = run_tool(q(file("limits.xyz")) + " " + q(file("limits.ply")) + " --memory-limit 100M");
  CHECK(within.status == 0);
  CHECK(within.err.empty());
}

// The peak memory of a tiled run against the limit (issue 45): a cloud of 200,000 points whose
// run in memory takes several times the limit above the tool's own base (its run on a few
// points), run in tiles under --memory-limit 10M. Measured: base 6.9 MB, in memory +70 MB,
// in tiles +25 MB. Not under the sanitizers (their shadow memory is no measure of the tool's).
TEST_CASE("tool: --memory-limit bounds the peak memory of a run in tiles, a few times the limit above the base")
{
#ifdef PSC_TEST_MEMORY_SANITIZED
  skip_test("peak memory is not measured under the sanitizers");
#else
  {
    std::ofstream out(file("peak_terrain.xyz"));
    out.precision(10);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> jitter(-0.25, 0.25);
    for(int i = 0; i < 500; ++i)
      for(int j = 0; j < 400; ++j)
      {
        const double x = i + jitter(random), y = j + jitter(random);
        out << x << " " << y << " " << 5 * std::sin(0.05 * x) * std::cos(0.04 * y) << "\n";
      }
  }
  write_xyz(file("peak_small.xyz"), plane(20, 0.2), false);
  const std::string options = " --neighbors 40 --orient +z";
  const std::pair<int, long> base = run_tool_peak_kb(q(file("peak_small.xyz")) + " " + q(file("peak.ply")) + options);
  const std::pair<int, long> whole =
    run_tool_peak_kb(q(file("peak_terrain.xyz")) + " " + q(file("peak.ply")) + options);
  const std::pair<int, long> tiled =
    run_tool_peak_kb(q(file("peak_terrain.xyz")) + " " + q(file("peak.ply")) + options + " --memory-limit 10M");
  REQUIRE(base.first == 0);
  REQUIRE(whole.first == 0);
  REQUIRE(tiled.first == 0);
  const long limit_kb = 10 * 1024;
  INFO("peak KB: base " << base.second << ", in memory " << whole.second << ", in tiles " << tiled.second);
  CHECK(whole.second - base.second > 6 * limit_kb);  // (so that the limit has something to bound)
  CHECK(tiled.second - base.second < 4 * limit_kb);
  CHECK(2 * tiled.second < whole.second);
#endif
}
