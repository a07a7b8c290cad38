// Triangle meshes coded by a traversal of their triangles (docs/cnb.md, "Traversal-coded triangle mesh"):
// a region grows from one triangle across the edges of its border, and each step says in one symbol how
// the triangle beyond the border edge (the gate) meets the region. Most steps add a new vertex (its
// position predicted by completing the parallelogram of the gate's triangle, or from the cell a period
// before where the mesh repeats: cnb_mesh_period.hpp) or close on the border's neighbouring edge, so
// connectivity costs about a symbol per triangle and positions of box-like parts mostly predict exactly.
//
// The symbols are those of Rossignac's Edgebreaker (C, L, R, E; IEEE TVCG 5(1), 1999) and the border
// handling that of Gumhold and Strasser's cut-border machine (SIGGRAPH 1998): the border is a set of
// cyclic lists of edges. A triangle whose third vertex is already in the region but not beside the gate
// names that vertex by its number (Edgebreaker's S, which needs no number but a second decoding pass),
// and where that vertex is on the border the lists are split or joined there. A boundary edge is dropped
// by one symbol, and so is an edge whose far triangle the region reached another way (only where edges
// are not manifold). So any oriented triangle list is coded, manifold or not, with boundaries and
// handles, and the decoder replays the same list operations. Measured against Draco on library parts'
// certified meshes: bench/cnb_mesh_against_draco.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "formats/cnb/cnb_gate_shape.hpp"
#include "formats/cnb/cnb_geometry.hpp"
#include "formats/cnb/cnb_mesh_period.hpp"
#include "formats/cnb/cnb_numbers.hpp"
#include "formats/cnb/cnb_vertex_predictors.hpp"
#include "formats/cnb/cnb_vertex_values.hpp"

namespace cadnurbs::cnb {

namespace {

// The symbols, one byte each.
enum Symbol : uint8_t {
  new_vertex = 0,       // C: the far vertex is new; its position follows
  closes_next = 1,      // R: the far vertex ends the border edge after the gate
  closes_previous = 2,  // L: the far vertex starts the border edge before the gate
  closes_both = 3,      // E: both
  old_vertex = 4,       // the far vertex is an earlier one, named by its number
  no_triangle = 5,      // the gate is a boundary edge (or one whose far side is not paired)
  reached = 6,          // the gate's far triangle is already in the region
};
constexpr uint8_t symbol_count = 7;
static_assert(symbol_count == mesh_symbol_count, "a context for the symbols after each symbol");

// One edge of the border, directed so that the region lies on its left: from -> to in the triangle
// `apex` completes. The encoder also keeps the edge's half-edge in the input mesh. In a mesh group, `member`
// is the group's mesh that triangle belongs to (it predicts the member of the triangle beyond).
struct BorderEdge {
  int from, to, apex;
  int half_edge;
  int previous, next;  // places in the pool
  int member = 0;
};

// The border: cyclic lists of border edges over a pool (a removed edge's place is not reused: the pool
// grows by at most two per triangle). The gate's list is worked on; the others wait on a stack.
class Border {
 public:
  bool empty() const { return gate_ < 0; }
  int gate() const { return gate_; }
  BorderEdge& operator[](int i) { return pool_[i]; }

  // A new list of three edges; the gate is the first.
  void start(const std::array<BorderEdge, 3>& edges) {
    const int first = static_cast<int>(pool_.size());
    for (int k = 0; k < 3; ++k) {
      BorderEdge e = edges[k];
      e.previous = first + (k + 2) % 3;
      e.next = first + (k + 1) % 3;
      add(e);
    }
    gate_ = first;
  }
  // Takes up a waiting list when the gate's list is used up; false when none is left.
  bool resume() {
    while (gate_ < 0 && !waiting_.empty()) {
      if (alive_[waiting_.back()]) gate_ = waiting_.back();
      waiting_.pop_back();
    }
    return gate_ >= 0;
  }
  // Removes edge i; the gate moves to the edge after it (or its list is used up).
  void remove(int i) {
    alive_[i] = false;
    if (pool_[i].next == i) {
      gate_ = -1;
      return;
    }
    pool_[pool_[i].previous].next = pool_[i].next;
    pool_[pool_[i].next].previous = pool_[i].previous;
    gate_ = pool_[i].next;
  }
  // Puts `e` in place of edge i; the gate becomes `e`.
  int replace(int i, BorderEdge e) {
    const int at = static_cast<int>(pool_.size());
    if (pool_[i].next == i) {
      e.previous = e.next = at;
    } else {
      e.previous = pool_[i].previous;
      e.next = pool_[i].next;
      pool_[e.previous].next = at;
      pool_[e.next].previous = at;
    }
    alive_[i] = false;
    add(e);
    gate_ = at;
    return at;
  }
  // Puts `first` then `second` in place of edge i; the gate becomes `second`.
  void replace_by_two(int i, BorderEdge first, BorderEdge second) {
    const int a = replace(i, first);
    const int b = static_cast<int>(pool_.size());
    second.previous = a;
    second.next = pool_[a].next == a ? a : pool_[a].next;
    add(second);
    pool_[second.next].previous = b;
    pool_[a].next = b;
    if (pool_[a].previous == a) pool_[a].previous = b;
    gate_ = b;
  }
  // The latest border edge that starts at vertex v, or -1.
  int edge_from(int v) const {
    const auto found = starts_.find(v);
    if (found == starts_.end()) return -1;
    for (auto i = found->second.rbegin(); i != found->second.rend(); ++i)
      if (alive_[*i]) return *i;
    return -1;
  }
  // The border after the far triangle of gate g, whose edges are `left` (ending at its vertex v) and
  // `right` (starting at v), met the region as `symbol` says: closing on the edge before the gate, after
  // it, or both, or adding its two edges.
  void advance(uint8_t symbol, int g, const BorderEdge& left, const BorderEdge& right, int v) {
    const int before = pool_[g].previous, after = pool_[g].next;
    if (symbol == closes_both) {
      remove(before);
      remove(g);
      remove(after);
    } else if (symbol == closes_previous) {
      remove(before);
      replace(g, right);
    } else if (symbol == closes_next) {
      remove(after);
      replace(g, left);
    } else {
      place(g, left, right, v);
    }
  }

  // The far triangle's edges `first` (ending at v) and `second` (starting at v) in place of edge i; where
  // v is on the border already, the lists are joined there (split or merged).
  void place(int i, const BorderEdge& first, const BorderEdge& second, int v) {
    const int at_v = edge_from(v);
    if (at_v >= 0)
      join_at(i, first, second, at_v);
    else
      replace_by_two(i, first, second);
  }

 private:
  // Puts `first` (ending at v) and `second` (starting at v) in place of edge i, where v already starts
  // the border edge `at_v`, and then exchanges the successors of `first` and of the edge before at_v:
  // first runs on into at_v, and that edge into second. On one list this splits it in two (the one
  // through `first` waits); on two lists it joins them. (Lists are only lists of edges: where a boundary
  // edge was removed, neighbours need not share a vertex, so no case is ruled out and the exchange is the
  // one operation that is right in all of them.) The gate becomes `second`.
  void join_at(int i, BorderEdge first, BorderEdge second, int at_v) {
    replace_by_two(i, first, second);
    const int f = pool_[gate_].previous, x = pool_[at_v].previous;
    const int after_f = pool_[f].next, after_x = pool_[x].next;
    pool_[f].next = after_x;
    pool_[after_x].previous = f;
    pool_[x].next = after_f;
    pool_[after_f].previous = x;
    waiting_.push_back(f);
  }

  void add(const BorderEdge& e) {
    starts_[e.from].push_back(static_cast<int>(pool_.size()));
    pool_.push_back(e);
    alive_.push_back(true);
  }
  std::vector<BorderEdge> pool_;
  std::vector<bool> alive_;
  std::unordered_map<int, std::vector<int>> starts_;
  std::vector<int> waiting_;
  int gate_ = -1;
};

// A triangle's member in a mesh group: 0 when it is the predicted one (the member of the triangle across
// the gate, or at a start the last triangle's), else member + 1; in the first context after a 0, else the
// second.
void write_member(ByteWriter& out, int member, int predicted, bool& after_other) {
  const uint8_t code = member == predicted ? 0 : static_cast<uint8_t>(member + 1);
  out.byte(code, Field::mesh_member, after_other);
  after_other = code != 0;
}
int read_member(ByteReader& in, int predicted, int member_count, bool& after_other) {
  const size_t at = in.offset();
  const uint8_t code = in.byte(Field::mesh_member, after_other);
  after_other = code != 0;
  if (code == 0) return predicted;
  if (code > member_count)
    in.fail("member " + std::to_string(code - 1) + " of a group of " + std::to_string(member_count) + " meshes", at);
  return code - 1;
}

// The border's polyline next to gate g (cnb_vertex_predictors.hpp): the two points after its end along
// the edges after it (`after`), or before its start along the edges before it; none where the gate's list
// holds fewer than three edges.
std::optional<BorderChain> border_chain(Border& border, int g, const std::vector<GridPoint>& grid, bool after) {
  const int first = after ? border[g].next : border[g].previous;
  if (first == g) return std::nullopt;
  const int second = after ? border[first].next : border[first].previous;
  if (second == g) return std::nullopt;
  if (after) return BorderChain{grid[border[first].to], grid[border[second].to]};
  return BorderChain{grid[border[first].from], grid[border[second].from]};
}

// The predictions of the vertex beyond gate g (version 8 on).
std::array<GridPoint, vertex_predictor_count> gate_predictions(Border& border, int g,
                                                               const std::vector<GridPoint>& grid) {
  const BorderEdge& gate = border[g];
  return vertex_predictions(grid[gate.from], grid[gate.to], grid[gate.apex], border_chain(border, g, grid, true),
                            border_chain(border, g, grid, false));
}

// The shape of the border after gate g (version 9 on): the context of its symbol after a new vertex.
int shape_at(Border& border, int g, const std::vector<GridPoint>& grid) {
  const BorderEdge& gate = border[g];
  std::optional<GridPoint> after;
  if (gate.next != g) after = grid[border[gate.next].to];
  return gate_shape(grid[gate.from], grid[gate.to], grid[gate.apex], after);
}

// An earlier vertex beyond a gate (version 9 on) is named by its place along the gate's list: 2 d + 1 for
// the start of the d-th edge after the gate, 2 d + 2 for the end of the d-th edge before it, d below
// farthest_border_place (a reader walks no farther); 0 where it is not so near (then by its number).
constexpr int farthest_border_place = 1024;

// The place of vertex v along the list of gate g, the nearest first; 0 when not within reach.
uint64_t border_place(Border& border, int g, int v) {
  int after = border[g].next, before = border[g].previous;
  for (int d = 0; d < farthest_border_place; ++d) {
    if (after == g && before == g) break;
    if (after != g) {
      if (border[after].from == v) return 2 * static_cast<uint64_t>(d) + 1;
      after = border[after].next;
    }
    if (before != g) {
      if (border[before].to == v) return 2 * static_cast<uint64_t>(d) + 2;
      before = border[before].previous;
    }
  }
  return 0;
}

class TraversalEncoder {
 public:
  // `members` (may be null): each triangle's mesh in a group, coded after the triangle.
  TraversalEncoder(ByteWriter& out, const TriangleMesh& mesh, double q, CodingState& state,
                   const std::vector<int>* members)
      : out_(out), mesh_(mesh), members_(members), state_(state), q_(q), grid_(grid_points(mesh, q)),
        value_coding_(value_coding(state.version)) {
    pair_half_edges();
  }

  void encode() {
    const size_t triangles = mesh_.triangles.size();
    out_.varuint(used_vertex_count(), Field::count);
    out_.varuint(triangles, Field::count);
    ++state_.traversal_meshes;
    // (The writer writes version 5: the period follows.)
    std::vector<GridPoint> used;
    for (const auto& t : mesh_.triangles)
      for (int v : t) used.push_back(grid_[v]);
    const GridPoint period = !state_.mesh_periods ? GridPoint{0, 0, 0}
                             : state_.periods     ? state_.periods->period_of(used)
                                                  : dominant_period(used);
    // (Version 8: the first coordinate carries whether each new vertex names its predictor, so that a mesh
    // without costs what it did before.)
    const int64_t flag = state_.mesh_predictors ? 1 : 0;
    for (int k = 0; k < 3; ++k) out_.varsint(k == 0 ? 2 * period[k] + flag : period[k], Field::point);
    repeats_ = PeriodPredictor(period);
    if (repeats_.active()) ++state_.periodic_meshes;
    visited_.assign(triangles, false);
    number_.assign(mesh_.positions.size(), -1);
    size_t first_unvisited = 0;
    while (written_ < triangles) {
      if (border_.empty() && !border_.resume()) {
        while (visited_[first_unvisited]) ++first_unvisited;
        start(static_cast<int>(first_unvisited));
      } else {
        step();
      }
    }
  }

 private:
  int corner(int half_edge, int offset) const { return mesh_.triangles[half_edge / 3][(half_edge % 3 + offset) % 3]; }

  // Half-edge h = 3t + k runs from corner k to corner k+1 of triangle t. It pairs with the opposite
  // half-edge when each direction of that edge occurs exactly once.
  void pair_half_edges() {
    const int n = static_cast<int>(3 * mesh_.triangles.size());
    std::vector<std::array<int, 3>> by_ends(n);  // (from, to, half-edge), sorted
    for (int h = 0; h < n; ++h) by_ends[h] = {corner(h, 0), corner(h, 1), h};
    std::sort(by_ends.begin(), by_ends.end());
    // The half-edges running from a to b: a range of by_ends.
    const auto running = [&](int a, int b) {
      return std::equal_range(by_ends.begin(), by_ends.end(), std::array<int, 3>{a, b, 0},
                              [](const auto& x, const auto& y) { return x[0] != y[0] ? x[0] < y[0] : x[1] < y[1]; });
    };
    twin_.assign(n, -1);
    for (int h = 0; h < n; ++h) {
      const auto same = running(corner(h, 0), corner(h, 1));
      const auto opposite = running(corner(h, 1), corner(h, 0));
      if (same.second - same.first == 1 && opposite.second - opposite.first == 1) twin_[h] = (*opposite.first)[2];
    }
  }

  size_t used_vertex_count() const {
    std::vector<bool> used(mesh_.positions.size(), false);
    for (const auto& t : mesh_.triangles)
      for (int v : t) used[v] = true;
    return static_cast<size_t>(std::count(used.begin(), used.end(), true));
  }

  // A symbol, in the model of those that follow the symbol before it (version 9 on, after a new vertex
  // beyond a gate, in the model of the border's shape there).
  void symbol(uint8_t s) {
    out_.byte_in(s, gate_shape_ >= 0 ? gate_symbol_context(gate_shape_) : symbol_context(previous_));
    previous_ = s;
  }

  // The grid point new vertex v is written at: its nearest, or (state_.free_radius > 0) the one within
  // that many steps of it that costs fewest bits against `predicted` (the nearest among equals). The
  // vertex still moves no farther than the points' bound, and the reader decodes whichever is written.
  GridPoint written_point(int v, const GridPoint& predicted) const {
    const GridPoint& nearest = grid_[v];
    const double radius = state_.free_radius;
    if (!(radius > 0) || (state_.locked_points && state_.locked_points->count(nearest))) return nearest;
    const Eigen::Vector3d at = mesh_.positions[v] / q_;
    const auto distance = [&](const GridPoint& g) {
      return (Eigen::Vector3d(static_cast<double>(g[0]), static_cast<double>(g[1]), static_cast<double>(g[2])) - at)
          .norm();
    };
    GridPoint best = nearest;
    double best_bits = state_.mesh_values.estimated_bits(nearest, predicted, value_coding_), best_distance = distance(nearest);
    const double reach = radius * (1.0 - 1e-9);  // rounding in `at` stays inside the bound
    GridPoint g;
    for (g[0] = static_cast<int64_t>(std::ceil(at.x() - reach)); g[0] <= static_cast<int64_t>(std::floor(at.x() + reach)); ++g[0])
      for (g[1] = static_cast<int64_t>(std::ceil(at.y() - reach)); g[1] <= static_cast<int64_t>(std::floor(at.y() + reach)); ++g[1])
        for (g[2] = static_cast<int64_t>(std::ceil(at.z() - reach)); g[2] <= static_cast<int64_t>(std::floor(at.z() + reach)); ++g[2]) {
          const double d = distance(g);
          if (d > reach) continue;
          const double bits = state_.mesh_values.estimated_bits(g, predicted, value_coding_);
          if (bits < best_bits || (bits == best_bits && d < best_distance)) best = g, best_bits = bits, best_distance = d;
        }
    return best;
  }

  // Names vertex v: new (its position predicted by `predicted`) or by its number.
  void vertex(int v, const GridPoint& predicted) {
    if (number_[v] < 0) {
      new_vertex_at(v, written_point(v, predicted), predicted, -1);
    } else {
      symbol(old_vertex);
      write_number(v);
    }
  }

  // Earlier vertex v's number, counted back from the last vertex.
  void write_number(int v) { out_.varuint(static_cast<uint64_t>(count_ - 1 - number_[v]), Field::index); }

  // Names new vertex v beyond a gate whose predictions are `predictions` (version 8) by whichever
  // prediction its nearest grid point costs fewest estimated bits against, the predictor's symbol
  // included; then at the grid point that prediction codes cheapest (written_point).
  void predicted_vertex(int v, const std::array<GridPoint, vertex_predictor_count>& predictions) {
    int best = 0;
    double best_bits = 0;
    for (int k = 0; k < vertex_predictor_count; ++k) {
      const double bits = state_.mesh_values.estimated_bits(grid_[v], predictions[k], value_coding_) + predictor_bits(k);
      if (k == 0 || bits < best_bits || (bits == best_bits && k == previous_predictor_)) best = k, best_bits = bits;
    }
    new_vertex_at(v, written_point(v, predictions[best]), predictions[best], best);
  }

  // About what predictor k costs after the previous one: its share of the choices made after that one so
  // far in this mesh (each counted from 1).
  double predictor_bits(int k) const {
    const auto& after = predictor_counts_[previous_predictor_];
    double total = 0;
    for (double c : after) total += c;
    return -std::log2(after[k] / total);
  }

  // Writes new vertex v at grid point `written`, against `predicted`, after its predictor (-1: none).
  void new_vertex_at(int v, const GridPoint& written, const GridPoint& predicted, int predictor) {
    if (written != grid_[v]) ++state_.vertices_off_nearest;
    grid_[v] = written;
    symbol(new_vertex);
    if (predictor >= 0) {
      out_.byte_in(static_cast<uint8_t>(predictor), predictor_context(previous_predictor_));
      predictor_counts_[previous_predictor_][predictor] += 1;
      previous_predictor_ = static_cast<uint8_t>(predictor);
    }
    state_.mesh_values.write(out_, grid_[v], predicted, value_coding_);
    repeats_.add_vertex(count_, grid_[v]);
    number_[v] = count_++;
    state_.last_mesh_vertex = grid_[v];
  }

  bool gate_shapes() const { return state_.version >= 9; }

  // Names earlier vertex v beyond gate g: from version 9 by its place along the border (0 where not within
  // reach, then by its number), before by its number.
  void earlier_vertex_beyond(int g, int v) {
    symbol(old_vertex);
    const uint64_t place = gate_shapes() ? border_place(border_, g, v) : 0;
    if (gate_shapes()) out_.varuint_in(place, Field::index, border_place_context());
    if (place == 0) write_number(v);
  }

  // The member of triangle t, predicted as `predicted` (nothing outside a group).
  int member(int t, int predicted) {
    if (!members_) return 0;
    const int m = (*members_)[t];
    write_member(out_, m, predicted, member_after_other_);
    last_member_ = m;
    return m;
  }

  void start(int t) {
    gate_shape_ = -1;  // a start's symbols take the contexts of version 8
    visited_[t] = true;
    ++written_;
    for (int k = 0; k < 3; ++k) vertex(mesh_.triangles[t][k], state_.last_mesh_vertex);
    const auto& corners = mesh_.triangles[t];
    repeats_.add_triangle(number_[corners[0]], number_[corners[1]], number_[corners[2]]);
    const int m = member(t, last_member_);
    std::array<BorderEdge, 3> edges;
    for (int k = 0; k < 3; ++k)
      edges[k] = {corner(3 * t + k, 0), corner(3 * t + k, 1), corner(3 * t + k, 2), 3 * t + k, 0, 0, m};
    border_.start(edges);
  }

  void step() {
    const int g = border_.gate();
    const BorderEdge gate = border_[g];
    gate_shape_ = gate_shapes() && previous_ == new_vertex ? shape_at(border_, g, grid_) : -1;
    const int far = twin_[gate.half_edge];
    if (far < 0 || visited_[far / 3]) {
      // (Version 9 on, one symbol for both: the reader drops the gate either way.)
      symbol(far < 0 || gate_shapes() ? no_triangle : reached);
      border_.remove(g);
      return;
    }
    visited_[far / 3] = true;
    ++written_;
    // The far triangle runs to -> from -> v; its edges from -> v and v -> to join the border.
    const int v = corner(far, 2);
    const int to_apex = 3 * (far / 3) + (far % 3 + 1) % 3;  // from -> v
    const int apex_to = 3 * (far / 3) + (far % 3 + 2) % 3;  // v -> to
    const BorderEdge& before = border_[gate.previous];
    const BorderEdge& after = border_[gate.next];
    const bool closes_before = gate.previous != g && before.half_edge == twin_[to_apex] && twin_[to_apex] >= 0;
    const bool closes_after = gate.next != g && after.half_edge == twin_[apex_to] && twin_[apex_to] >= 0;
    uint8_t s = closes_before && closes_after ? closes_both
                : closes_before               ? closes_previous
                : closes_after                ? closes_next
                                              : new_vertex;
    if (s != new_vertex) {
      symbol(s);
    } else if (number_[v] >= 0) {  // an earlier vertex: no prediction
      earlier_vertex_beyond(g, v);
    } else {
      const auto by_period = repeats_.predict(grid_[gate.from], grid_[gate.to], grid_[gate.apex]);
      if (by_period || !state_.mesh_predictors)
        vertex(v, by_period.value_or(parallelogram(grid_[gate.from], grid_[gate.to], grid_[gate.apex])));
      else
        predicted_vertex(v, gate_predictions(border_, g, grid_));
    }
    repeats_.add_triangle(number_[gate.to], number_[gate.from], number_[v]);
    const int m = member(far / 3, gate.member);
    const BorderEdge left{gate.from, v, gate.to, to_apex, 0, 0, m}, right{v, gate.to, gate.from, apex_to, 0, 0, m};
    border_.advance(s, g, left, right, v);
  }

  ByteWriter& out_;
  const TriangleMesh& mesh_;
  const std::vector<int>* members_;
  CodingState& state_;
  double q_;
  int last_member_ = 0;
  bool member_after_other_ = false;
  std::vector<GridPoint> grid_;
  std::vector<int> twin_;
  std::vector<bool> visited_;
  std::vector<int> number_;  // input vertex -> decoded vertex number, -1 before it is met
  int count_ = 0;
  size_t written_ = 0;
  uint8_t previous_ = new_vertex;
  int gate_shape_ = -1;  // version 9 on: the shape after the gate, the context of a symbol after a new vertex; else -1
  ValueCoding value_coding_;
  uint8_t previous_predictor_ = 0;
  std::array<std::array<double, vertex_predictor_count>, vertex_predictor_count> predictor_counts_{
      {{1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}}};
  Border border_;
  PeriodPredictor repeats_{{0, 0, 0}};
};

class TraversalDecoder {
 public:
  // `member_count` > 0: a group's union, each triangle's member read after it into `members`.
  TraversalDecoder(ByteReader& in, double q, CodingState& state, int member_count = 0,
                   std::vector<int>* members = nullptr)
      : in_(in), q_(q), values_(state.mesh_values), last_(state.last_mesh_vertex), member_count_(member_count),
        members_(members), version_4_contexts_(state.version >= 4), period_(state.version >= 5),
        predictor_flag_(state.version >= 8), gate_shapes_(state.version >= 9), value_coding_(value_coding(state.version)) {}

  TriangleMesh decode() {
    vertex_count_ = in_.count(4);
    const size_t triangles = in_.count(1);
    if (period_) {
      GridPoint period;
      for (int k = 0; k < 3; ++k) {
        const size_t at = in_.offset();
        period[k] = in_.varsint(Field::point);
        if (k == 0 && predictor_flag_) {  // 2 x + flag, the flag its lowest bit
          predictors_ = (period[0] & 1) != 0;
          period[0] = (period[0] - (predictors_ ? 1 : 0)) / 2;
        }
        if (std::abs(static_cast<double>(period[k])) > 0x1p52) in_.fail("mesh period outside the grid's range", at);
      }
      repeats_ = PeriodPredictor(period);
    }
    grid_.reserve(vertex_count_);
    mesh_.triangles.reserve(triangles);
    while (mesh_.triangles.size() < triangles) {
      if (border_.empty() && !border_.resume())
        start();
      else
        step();
    }
    if (grid_.size() != vertex_count_)
      in_.fail(std::to_string(grid_.size()) + " vertices met where " + std::to_string(vertex_count_) +
               " were declared");
    mesh_.positions.reserve(grid_.size());
    for (const auto& p : grid_)
      mesh_.positions.emplace_back(static_cast<double>(p[0]) * q_, static_cast<double>(p[1]) * q_,
                                   static_cast<double>(p[2]) * q_);
    return std::move(mesh_);
  }

 private:
  int vertex(uint8_t symbol, size_t at, const GridPoint& predicted) {
    if (symbol == new_vertex) {
      if (grid_.size() >= vertex_count_)
        in_.fail("more vertices than the " + std::to_string(vertex_count_) + " declared", at);
      const GridPoint p = values_.read(in_, predicted, value_coding_);
      repeats_.add_vertex(static_cast<int>(grid_.size()), p);
      grid_.push_back(p);
      last_ = p;
      return static_cast<int>(grid_.size() - 1);
    }
    if (symbol != old_vertex) in_.fail("symbol " + std::to_string(symbol) + " where a vertex is named", at);
    const size_t ref_at = in_.offset();
    const uint64_t back = in_.varuint(Field::index);
    if (back >= grid_.size())
      in_.fail("vertex " + std::to_string(back + 1) + " back, with " + std::to_string(grid_.size()) + " before it",
               ref_at);
    return static_cast<int>(grid_.size() - 1 - back);
  }

  // Version 4 on: in the model of the symbols that follow the one before (version 9 on, after a new vertex
  // beyond a gate, of the border's shape there); before: of those that follow a new vertex or of those
  // that follow anything else.
  uint8_t symbol() {
    const size_t at = in_.offset();
    previous_ = gate_shape_ >= 0     ? in_.byte_in(gate_symbol_context(gate_shape_))
                : version_4_contexts_ ? in_.byte_in(symbol_context(previous_))
                                      : in_.byte(Field::symbol, previous_ != new_vertex);
    // (Checked here, since the next symbol's context depends on it.)
    if (version_4_contexts_ && previous_ >= symbol_count)
      in_.fail("unknown mesh symbol " + std::to_string(previous_), at);
    return previous_;
  }

  // Adds the triangle and reads its member (predicted as `predicted`).
  int triangle(int a, int b, int c, size_t at, int predicted) {
    if (a == b || b == c || c == a) in_.fail("a triangle with a repeated vertex", at);
    mesh_.triangles.push_back({a, b, c});
    if (member_count_ == 0) return 0;
    last_member_ = read_member(in_, predicted, member_count_, member_after_other_);
    members_->push_back(last_member_);
    return last_member_;
  }

  void start() {
    gate_shape_ = -1;
    std::array<int, 3> v;
    for (int k = 0; k < 3; ++k) {
      const size_t at = in_.offset();
      v[k] = vertex(symbol(), at, last_);
    }
    const int m = triangle(v[0], v[1], v[2], in_.offset(), last_member_);
    repeats_.add_triangle(v[0], v[1], v[2]);
    border_.start({BorderEdge{v[0], v[1], v[2], -1, 0, 0, m}, BorderEdge{v[1], v[2], v[0], -1, 0, 0, m},
                   BorderEdge{v[2], v[0], v[1], -1, 0, 0, m}});
  }

  void step() {
    const size_t at = in_.offset();
    const int g = border_.gate();
    gate_shape_ = gate_shapes_ && previous_ == new_vertex ? shape_at(border_, g, grid_) : -1;
    const uint8_t symbol = this->symbol();
    const BorderEdge gate = border_[g];
    if (symbol >= symbol_count) in_.fail("unknown mesh symbol " + std::to_string(symbol), at);
    if (symbol == no_triangle || symbol == reached) {
      border_.remove(g);
      return;
    }
    const bool uses_before = symbol == closes_previous || symbol == closes_both;
    const bool uses_after = symbol == closes_next || symbol == closes_both;
    const int needed = 1 + (uses_before ? 1 : 0) + (uses_after ? 1 : 0);
    if (border_size_below(g, needed)) in_.fail("the border is too short for mesh symbol " + std::to_string(symbol), at);
    int v;
    if (uses_before)
      v = border_[gate.previous].from;
    else if (uses_after)
      v = border_[gate.next].to;
    else if (symbol == old_vertex && gate_shapes_)
      v = vertex_at_place(g, at);
    else
      v = vertex(symbol, at, predicted_beyond(g, symbol));
    const int m = triangle(gate.to, gate.from, v, at, gate.member);
    repeats_.add_triangle(gate.to, gate.from, v);
    const BorderEdge left{gate.from, v, gate.to, -1, 0, 0, m}, right{v, gate.to, gate.from, -1, 0, 0, m};
    border_.advance(symbol, g, left, right, v);
  }

  // Where the vertex beyond gate g is predicted: by the period, else (where the mesh names predictors and
  // the vertex is new) by the predictor read here, else by the parallelogram.
  GridPoint predicted_beyond(int g, uint8_t symbol) {
    const BorderEdge& gate = border_[g];
    const auto by_period = repeats_.predict(grid_[gate.from], grid_[gate.to], grid_[gate.apex]);
    if (by_period) return *by_period;
    if (!predictors_ || symbol != new_vertex) return parallelogram(grid_[gate.from], grid_[gate.to], grid_[gate.apex]);
    const size_t at = in_.offset();
    const uint8_t predictor = in_.byte_in(predictor_context(previous_predictor_));
    if (predictor >= vertex_predictor_count) in_.fail("unknown vertex predictor " + std::to_string(predictor), at);
    previous_predictor_ = predictor;
    return gate_predictions(border_, g, grid_)[predictor];
  }

  // The earlier vertex named by its place along the list of gate g (version 9 on), else by its number.
  int vertex_at_place(int g, size_t at) {
    const size_t place_at = in_.offset();
    const uint64_t place = in_.varuint_in(Field::index, border_place_context());
    if (place == 0) return vertex(old_vertex, at, {0, 0, 0});
    const uint64_t d = (place - 1) / 2;
    const bool after = (place - 1) % 2 == 0;
    if (d >= farthest_border_place)
      in_.fail("border place " + std::to_string(place) + " beyond the " + std::to_string(farthest_border_place) +
                   " edges a reader walks",
               place_at);
    int i = after ? border_[g].next : border_[g].previous;
    for (uint64_t k = 0; k < d && i != g; ++k) i = after ? border_[i].next : border_[i].previous;
    if (i == g) in_.fail("border place " + std::to_string(place) + " beyond the gate's border", place_at);
    return after ? border_[i].from : border_[i].to;
  }

  // Whether the loop through edge g holds fewer than n distinct edges.
  bool border_size_below(int g, int n) {
    int i = g;
    for (int k = 1; k < n; ++k) {
      i = border_[i].next;
      if (i == g) return true;
    }
    return false;
  }

  ByteReader& in_;
  double q_;
  size_t vertex_count_ = 0;
  std::vector<GridPoint> grid_;
  TriangleMesh mesh_;
  VertexValues& values_;
  GridPoint& last_;
  uint8_t previous_ = new_vertex;
  Border border_;
  int member_count_;
  std::vector<int>* members_;
  int last_member_ = 0;
  bool member_after_other_ = false;
  bool version_4_contexts_;  // symbols by the one before
  bool period_;              // version 5 on: the mesh's period, and vertices predicted by it
  bool predictor_flag_;      // version 8 on: the period's x says too whether new vertices name their predictor
  bool predictors_ = false;
  bool gate_shapes_;     // version 9 on: symbols after a new vertex by the shape after the gate, earlier
                         // vertices by their place along the border
  int gate_shape_ = -1;  // that shape while a step reads its symbol; else -1
  ValueCoding value_coding_;
  uint8_t previous_predictor_ = 0;
  PeriodPredictor repeats_{{0, 0, 0}};
};

}  // namespace

bool traversal_codable(const TriangleMesh& mesh) {
  if (!mesh.corner_normals.empty() || mesh.triangles.empty()) return false;
  for (const auto& t : mesh.triangles)
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return false;
  return true;
}

void write_traversal_mesh(ByteWriter& out, const TriangleMesh& mesh, double q, CodingState& state,
                          const std::vector<int>* members) {
  TraversalEncoder(out, mesh, q, state, members).encode();
}

TriangleMesh read_traversal_mesh(ByteReader& in, double q, CodingState& state, int member_count,
                                 std::vector<int>* members) {
  return TraversalDecoder(in, q, state, member_count, members).decode();
}

}  // namespace cadnurbs::cnb
