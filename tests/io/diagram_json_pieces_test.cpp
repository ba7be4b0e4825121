// The arc graph's text rendered in pieces on several threads (io/diagram_json_write.h,
// io/ordered_pieces.h): whatever the cut and the thread count, the text is the one the serial writer
// wrote before (golden text below), and it reads back to the same diagram bit for bit.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "diagram_samples.h"
#include "io/diagram_json.h"
#include "io/diagram_json_write.h"
#include "io/ordered_pieces.h"

namespace covmap::io {
namespace {

using detail::DiagramTextPieces;
using testing::expect_identical;
using testing::sample;

// The text of sample() and of an empty diagram as written by the serial writer before the text was
// cut into pieces (captured from that build): the pieces must not change a byte of it.
constexpr std::string_view kSampleText = R"({"format":"covmap.arcgraph/1",
"sites":[
  {"id":"a","x":0.1,"y":-0.0,"weight":0.3333333333333333},
  {"id":"b","x":5e-324,"y":1e+300,"weight":2.0,"name":"Mast \"b\", north"},
  {"id":"c & <d>","x":-7.25,"y":1.0000000000000002,"weight":1.7976931348623157e+308}
],
"nodes":[
  {"x":0.3333333333333333,"y":0.6666666666666666},
  {"x":-1e-300,"y":123456789.12345679},
  {"x":0.30000000000000004,"y":0.0}
],
"arcs":[
  {"from":null,"to":null,"circle":{"cx":-1.0,"cy":0.0,"r":2.0,"ccw":true},"sites":[0,1]},
  {"from":0,"to":1,"circle":{"cx":0.1,"cy":0.2,"r":1.4142135623730951,"ccw":false},"sites":[1,2]},
  {"from":null,"to":null,"line":{"x":1.0,"y":0.0,"dx":0.0,"dy":1.0},"sites":[0,2]},
  {"from":2,"to":null,"line":{"x":0.1,"y":0.7,"dx":-0.7071067811865476,"dy":0.7071067811865476},"sites":[2,1]},
  {"from":null,"to":0,"line":{"x":3.0,"y":3.0,"dx":1.0,"dy":0.0},"sites":[1,0]},
  {"from":1,"to":2,"line":{"x":0.0,"y":0.0,"dx":1.0,"dy":1.0},"sites":[2,null],"frame":true}
],
"faces":[
  {"site":0,"bounded":true,"orphan":false,"boundaries":[[[0,true]]]},
  {"site":1,"bounded":false,"orphan":false,"boundaries":[[[0,false]],[[3,false],[4,true]]]},
  {"site":2,"bounded":true,"orphan":true,"boundaries":[[[1,true],[5,false],[3,true]]]}
],
"clip":[
  [-10.0,-10.0],
  [10.0,-10.0],
  [10.0,10.0],
  [-10.0,0.1]
]
}
)";

constexpr std::string_view kEmptyText = R"({"format":"covmap.arcgraph/1",
"sites":[],
"nodes":[],
"arcs":[],
"faces":[],
"clip":[]
}
)";

std::string render(const Diagram& d, std::size_t piece_bytes, int threads) {
  DiagramTextPieces options;
  options.piece_bytes = piece_bytes;
  options.threads = threads;
  std::string text;
  detail::render_diagram_json(d, options, [&text](std::string_view piece) { text.append(piece); });
  return text;
}

std::string streamed(const Diagram& d) {
  std::ostringstream out;
  write_diagram_json(d, out);
  return out.str();
}

// A diagram the reader accepts (structure only, like sample()) with `n` sites, about 2n nodes, 3n
// arcs of every kind (full and partial circles, lines, rays, frame arcs), a face per site with one to
// three cycles, and a clip square; random doubles of every magnitude.
Diagram synthetic(int n, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto any = [&] { return std::ldexp(unit(random) - 0.5, static_cast<int>(random() % 80) - 40); };
  Diagram d;
  for (int i = 0; i < n; ++i) d.sites.push_back({"s" + std::to_string(i), i + unit(random), any(), 0.5 + unit(random)});
  if (n > 0) d.sites[0].name = "first \"site\"";
  if (n < 2) return d;
  const int nodes = 2 * n;
  for (int i = 0; i < nodes; ++i) d.nodes.push_back({any(), any()});
  for (int i = 0; i < 3 * n; ++i) {
    Arc arc;
    arc.left_site = i % n;
    arc.right_site = (i + 1) % n;
    switch (i % 5) {
      case 0: arc.curve = Circle{any(), any(), 1.0 + unit(random)}; break;  // full circle
      case 1:
        arc.curve = Circle{any(), any(), unit(random) + 1e-3};
        arc.from = i % nodes, arc.to = (i + 7) % nodes, arc.ccw = i % 2 == 0;
        break;
      case 2: arc.curve = Line{any(), any(), 1.0, any()}; break;  // whole line
      case 3: arc.curve = Line{any(), any(), -0.6, 0.8}, arc.from = i % nodes; break;  // ray
      default: arc.curve = Line{any(), any(), 0.0, -1.0}, arc.from = i % nodes, arc.to = (i + 1) % nodes;
    }
    if (i % 11 == 10) arc.frame = true, arc.right_site = kNone;
    d.arcs.push_back(arc);
  }
  const int arcs = static_cast<int>(d.arcs.size());
  for (int s = 0; s < n; ++s) {
    add_face(d, {s, s % 3 != 0, s % 7 == 6});
    for (int c = 0; c <= s % 3; ++c) {
      std::vector<HalfArc> cycle;
      for (int k = 0; k <= (s + c) % 6; ++k) cycle.push_back({(s * 3 + c + k) % arcs, (s + k) % 2 == 0});
      add_cycle(d, cycle);
    }
  }
  d.clip = {{-1e6, -1e6}, {1e6, -1e6}, {1e6, 1e6}, {-1e6, 1e6}};
  return d;
}

TEST(DiagramJsonPieces, TextIsTheSerialWritersGoldenText) {
  EXPECT_EQ(streamed(sample()), kSampleText);
  EXPECT_EQ(diagram_json_text(sample()), kSampleText);
  EXPECT_EQ(streamed(Diagram{}), kEmptyText);
  EXPECT_EQ(diagram_json_text(Diagram{}), kEmptyText);
  // Every cut and thread count, down to one element per piece.
  for (const std::size_t piece_bytes : {std::size_t{1}, std::size_t{200}, std::size_t{1000}, std::numeric_limits<std::size_t>::max()}) {
    for (const int threads : {1, 2, 3}) {
      EXPECT_EQ(render(sample(), piece_bytes, threads), kSampleText) << piece_bytes << " bytes, " << threads << " threads";
      EXPECT_EQ(render(Diagram{}, piece_bytes, threads), kEmptyText) << piece_bytes << " bytes, " << threads << " threads";
    }
  }
}

TEST(DiagramJsonPieces, EveryCutGivesTheSameTextAndReadsBackExactly) {
  // Sizes around the cuts: no element, one, two, a prime count, and enough for many pieces.
  for (const int n : {0, 1, 2, 3, 7, 61, 500}) {
    const Diagram d = synthetic(n, 17 + static_cast<unsigned>(n));
    const std::string whole = render(d, std::numeric_limits<std::size_t>::max(), 1);  // one piece per array
    // A piece of one element, of two, of about a third of an array, and of all but the last.
    const std::size_t bound = detail::diagram_json_size_bound(d);
    for (const std::size_t piece_bytes : {std::size_t{1}, std::size_t{450}, bound / 12 + 1, bound - bound / 10}) {
      for (const int threads : {1, 2, 4}) {
        EXPECT_EQ(render(d, piece_bytes, threads), whole) << n << " sites, " << piece_bytes << " bytes, " << threads << " threads";
      }
    }
    EXPECT_EQ(streamed(d), whole) << n;
    EXPECT_EQ(diagram_json_text(d), whole) << n;
    EXPECT_LE(whole.size(), bound);
    if (n == 0) {
      EXPECT_EQ(whole, kEmptyText);
      continue;
    }
    SCOPED_TRACE(n);
    expect_identical(d, parse_diagram_json(whole, "pieces.json"));
  }
}

TEST(DiagramJsonPieces, LargeGraphIsCutAndThreadedByDefaultAndUnchanged) {
  // 4·10^3 sites: a length bound of several MB, so the default options cut it into dozens of pieces
  // and use every core the machine has.
  const Diagram d = synthetic(4000, 5);
  ASSERT_GT(detail::diagram_json_size_bound(d), 4 * detail::kThreadedTextBytes);
  const std::string whole = render(d, std::numeric_limits<std::size_t>::max(), 1);
  EXPECT_EQ(streamed(d), whole);
  EXPECT_EQ(diagram_json_text(d), whole);
  EXPECT_EQ(render(d, DiagramTextPieces{}.piece_bytes, 2), whole);
  expect_identical(d, parse_diagram_json(whole, "large.json"));
}

TEST(OrderedPieces, EmitsEveryPieceOnceInOrderOnTheCallingThread) {
  const auto caller = std::this_thread::get_id();
  for (const int threads : {1, 2, 3, 8}) {
    for (const std::size_t window : {std::size_t{1}, std::size_t{2}, std::size_t{5}}) {
      for (const std::size_t count : {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{97}}) {
        std::vector<std::size_t> emitted;
        bool on_caller = true;
        detail::render_pieces_in_order(
            count, {threads, window},
            // Uneven work, so that pieces finish out of order.
            [](std::size_t j, std::string& text) {
              volatile double x = 0;
              for (std::size_t k = 0; k < (j * 7919) % 20000; ++k) x = x + static_cast<double>(k);
              text = std::to_string(j);
            },
            [&](std::string_view piece) {
              on_caller = on_caller && std::this_thread::get_id() == caller;
              emitted.push_back(std::stoul(std::string(piece)));
            });
        ASSERT_EQ(emitted.size(), count) << threads << " threads, window " << window;
        for (std::size_t j = 0; j < count; ++j) EXPECT_EQ(emitted[j], j);
        EXPECT_TRUE(on_caller);
      }
    }
  }
}

TEST(OrderedPieces, HoldsAtMostTheWindow) {
  std::atomic<int> held{0}, most{0};
  detail::render_pieces_in_order(
      200, {3, 4},
      [&](std::size_t, std::string& text) {
        const int now = ++held;
        for (int seen = most; now > seen && !most.compare_exchange_weak(seen, now);) {
        }
        text = "x";
      },
      [&](std::string_view) { --held; });
  EXPECT_LE(most.load(), 4);
  EXPECT_EQ(held.load(), 0);
}

TEST(OrderedPieces, FailureStopsTheOthersAndReachesTheCaller) {
  for (const int threads : {1, 2, 4}) {
    // Rendering piece 40 throws: nothing from 40 on is emitted, and the error is the caller's.
    std::vector<std::size_t> emitted;
    EXPECT_THROW(detail::render_pieces_in_order(
                     1000, {threads, 6},
                     [](std::size_t j, std::string& text) {
                       if (j == 40) throw std::runtime_error("piece 40");
                       text = std::to_string(j);
                     },
                     [&](std::string_view piece) { emitted.push_back(std::stoul(std::string(piece))); }),
                 std::runtime_error);
    EXPECT_LE(emitted.size(), 40u) << threads;
    for (std::size_t j = 0; j < emitted.size(); ++j) EXPECT_EQ(emitted[j], j);
    // Emitting throws (a full disk): the same.
    std::size_t emits = 0;
    EXPECT_THROW(detail::render_pieces_in_order(
                     1000, {threads, 6}, [](std::size_t j, std::string& text) { text = std::to_string(j); },
                     [&](std::string_view) {
                       if (++emits == 10) throw std::runtime_error("disk full");
                     }),
                 std::runtime_error);
    EXPECT_EQ(emits, 10u) << threads;
  }
}

}  // namespace
}  // namespace covmap::io
