#include "core/search.hpp"
#include "core/thread_tag.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <unordered_map>

namespace mc {

namespace {

constexpr double kTie = 1e-3;  // cost tie tolerance (costs are normalised, ~1..3)

struct Node {
  std::vector<uint32_t> parts;  // sorted arena ids
  double cost, g, h;
  uint64_t seq;
};

class Search {
 public:
  Search(const SearchInput& in, const PartAnalysis& root)
      : in_(in), obj_(Objective::of_root(root.e_all, root.delta, *in.ctx.dec)) {
    for (uint32_t i = 0; i < in.pool.size(); ++i) pool_index_[in.pool[i]] = i;
    intern(root);
  }

  SearchResult run() {
    const auto& dec = *in_.ctx.dec;
    SearchResult res;
    Node root = make_node({0});
    if (root.h <= 0) return finish(root, res);
    auto worse = [](const Node& a, const Node& b) {
      if (a.cost != b.cost) return a.cost > b.cost;
      if (a.h != b.h) return a.h > b.h;
      return a.seq > b.seq;
    };
    std::priority_queue<Node, std::vector<Node>, decltype(worse)> open(worse);
    std::set<std::vector<uint32_t>> seen{root.parts};
    open.push(root);
    double bound = std::numeric_limits<double>::infinity();
    bool have_best = false;
    Node best{}, most_cut = root;
    auto offer_leaf = [&](const Node& n) {
      if (!have_best || n.cost < bound - kTie || (std::abs(n.cost - bound) <= kTie && n.h < best.h)) {
        best = n;
        have_best = true;
        bound = std::min(bound, n.cost);
      }
    };
    while (!open.empty()) {
      if (Clock::now() > in_.deadline) {
        res.deadline_hit = true;
        break;
      }
      if (res.expanded >= dec.node_budget) {
        res.budget_hit = true;
        break;
      }
      Node n = open.top();
      open.pop();
      if (n.cost >= bound) continue;
      ++res.expanded;
      if (n.h < most_cut.h) most_cut = n;
      std::vector<Node> kids = children(n);
      if (kids.empty()) {
        offer_leaf(n);  // dead end at this LoD
        continue;
      }
      for (Node& c : kids) {
        if (!seen.insert(c.parts).second) continue;
        if (c.h > 0) {
          if (c.cost < bound) open.push(std::move(c));
        } else {
          offer_leaf(c);
        }
      }
    }
    if (have_best) return finish(best, res);
    if (res.budget_hit && !res.deadline_hit) {
      // Out of budget without a leaf: finish greedily from the most decomposed node.
      Node n = open.empty() ? most_cut : open.top();
      for (int step = 0; step < 256 && Clock::now() <= in_.deadline; ++step) {
        auto kids = children(n);
        if (kids.empty()) break;
        n = kids.front();
        if (n.h <= 0) break;
      }
      return finish(n, res);
    }
    return finish(most_cut, res);
  }

 private:
  double part_cost(const PartAnalysis& p) const { return obj_.part_cost(p.delta, p.e_all); }

  static constexpr uint32_t kNew = UINT32_MAX;

  // The arena id of a part with these cells, or kNew.
  uint32_t find(const Bits& bits) const {
    const auto it = by_hash_.find(hash_bits(bits));
    if (it != by_hash_.end())
      for (uint32_t id : it->second)
        if (arena_[id].bits == bits) return id;
    return kNew;
  }

  uint32_t intern(PartAnalysis info) {
    auto& bucket = by_hash_[info.hash];
    for (uint32_t id : bucket)
      if (arena_[id].bits == info.bits) return id;
    // Children may only cut by planes the space was refined by.
    std::vector<uint32_t> kept;
    for (uint32_t c : info.candidates)
      if (pool_index_.count(c)) kept.push_back(c);
    info.candidates = std::move(kept);
    arena_.push_back(std::move(info));
    const uint32_t id = static_cast<uint32_t>(arena_.size() - 1);
    bucket.push_back(id);
    return id;
  }

  Node make_node(std::vector<uint32_t> parts) {
    std::sort(parts.begin(), parts.end());
    double sd = 0, se = 0;
    for (uint32_t p : parts) {
      sd += arena_[p].delta;
      se += arena_[p].e_all;
    }
    Node n;
    n.parts = std::move(parts);
    n.g = obj_.g(n.parts.size(), sd);
    n.h = obj_.h(se, sd);
    n.cost = obj_.cost(n.g, n.h);
    n.seq = seq_++;
    return n;
  }

  bool cuttable(uint32_t p) const { return arena_[p].e_sig > 0 && !arena_[p].candidates.empty(); }

  // Memoised splits of (part, plane); computed in parallel for a whole expansion.
  void ensure_splits(const std::vector<uint32_t>& parts) {
    std::vector<std::pair<uint32_t, uint32_t>> todo;
    for (uint32_t p : parts)
      for (uint32_t c : arena_[p].candidates)
        if (!splits_.count({p, c})) todo.emplace_back(p, c);
    if (todo.empty()) return;
    // Per split: each piece is either a part the arena already holds (the same cells reached by
    // cuts in another order; analysed once) or a newly analysed one.
    struct Piece {
      uint32_t known = kNew;
      PartAnalysis info;
    };
    std::vector<std::vector<Piece>> pieces(todo.size());
    const PlaneResolver lookup = [this](const Plane& g,
                                        const std::vector<uint32_t>&) -> std::optional<uint32_t> {
      for (uint32_t id : in_.pool)
        if (same_plane_in_box(g, in_.space->cx->planes()[id], in_.ctx.angle_rad, in_.ctx.dist, in_.ctx.box))
          return id;
      return std::nullopt;
    };
    auto body = [&](size_t i) {
      const auto [p, c] = todo[i];
      const Bits& bits = arena_[p].bits;
      const Bits& pos = in_.positive[pool_index_.at(c)];
      Bits a(bits.size()), b(bits.size());
      bool any_a = false, any_b = false;
      for (size_t w = 0; w < bits.size(); ++w) {
        a[w] = bits[w] & pos[w];
        b[w] = bits[w] & ~pos[w];
        any_a |= a[w] != 0;
        any_b |= b[w] != 0;
      }
      if (!any_a || !any_b) return;  // the plane does not cut this part
      for (const Bits* side : {&a, &b})
        for (Bits& comp : components(*in_.space, *side)) {
          // The arena is read-only while the splits are computed (interning happens after).
          if (const uint32_t id = find(comp); id != kNew) pieces[i].push_back({id, {}});
          else pieces[i].push_back({kNew, analyze_part(*in_.space, std::move(comp), in_.ctx, lookup)});
        }
    };
    tbb::parallel_for(size_t(0), todo.size(), with_thread_tag(body));
    for (size_t i = 0; i < todo.size(); ++i) {
      std::vector<uint32_t> ids;
      // A cut that leaves a piece touching itself along a new edge gives no valid solid: reject
      // cuts that add pinch edges (a root that already has some may still be cut).
      int pinches = 0;
      for (const Piece& piece : pieces[i])
        pinches += (piece.known == kNew ? piece.info : arena_[piece.known]).pinch_edges;
      if (pinches > arena_[todo[i].first].pinch_edges) pieces[i].clear();
      for (Piece& piece : pieces[i])
        ids.push_back(piece.known == kNew ? intern(std::move(piece.info)) : piece.known);
      splits_[todo[i]] = std::move(ids);
    }
  }

  // The best `max_children` children in cost order: per cuttable part a sorted list of options
  // (its valid cuts with their cost change); combinations enumerated lazily by total change.
  std::vector<Node> children(const Node& n) {
    const auto& dec = *in_.ctx.dec;
    std::vector<uint32_t> fixed, cut;
    for (uint32_t p : n.parts) (cuttable(p) ? cut : fixed).push_back(p);
    if (cut.empty()) return {};
    ensure_splits(cut);
    struct Option {
      double dcost;
      uint32_t plane_rank;
      const std::vector<uint32_t>* pieces;
    };
    std::vector<std::vector<Option>> options;
    std::vector<uint32_t> owners;
    for (uint32_t p : cut) {
      std::vector<Option> opts;
      const auto& cands = arena_[p].candidates;
      for (uint32_t r = 0; r < cands.size(); ++r) {
        const auto& pieces = splits_.at({p, cands[r]});
        if (pieces.empty()) continue;
        double d = -part_cost(arena_[p]);
        for (uint32_t q : pieces) d += part_cost(arena_[q]);
        opts.push_back({d, r, &pieces});
      }
      if (opts.empty()) {
        fixed.push_back(p);
        continue;
      }
      std::stable_sort(opts.begin(), opts.end(),
                       [](const Option& a, const Option& b) { return a.dcost < b.dcost; });
      options.push_back(std::move(opts));
      owners.push_back(p);
    }
    if (options.empty()) return {};
    const size_t limit = dec.max_children > 0 ? static_cast<size_t>(dec.max_children) : size_t(100000);
    // Lazy k-best over the product of sorted lists: successors increment one index at or after
    // the last incremented position, so each combination is produced exactly once.
    struct State {
      double sum;
      std::vector<uint32_t> idx;
      size_t last;
      uint64_t order;
    };
    auto later = [](const State& a, const State& b) {
      return a.sum != b.sum ? a.sum > b.sum : a.order > b.order;
    };
    std::priority_queue<State, std::vector<State>, decltype(later)> heap(later);
    uint64_t order = 0;
    State s0{0, std::vector<uint32_t>(options.size(), 0), 0, order++};
    for (size_t i = 0; i < options.size(); ++i) s0.sum += options[i][0].dcost;
    heap.push(s0);
    std::vector<Node> kids;
    while (!heap.empty() && kids.size() < limit) {
      State s = heap.top();
      heap.pop();
      std::vector<uint32_t> parts = fixed;
      for (size_t i = 0; i < options.size(); ++i) {
        const auto& pieces = *options[i][s.idx[i]].pieces;
        parts.insert(parts.end(), pieces.begin(), pieces.end());
      }
      kids.push_back(make_node(std::move(parts)));
      for (size_t i = s.last; i < options.size(); ++i) {
        if (s.idx[i] + 1 >= options[i].size()) continue;
        State t = s;
        t.sum += options[i][s.idx[i] + 1].dcost - options[i][s.idx[i]].dcost;
        ++t.idx[i];
        t.last = i;
        t.order = order++;
        heap.push(std::move(t));
      }
    }
    std::stable_sort(kids.begin(), kids.end(), [](const Node& a, const Node& b) {
      return a.cost != b.cost ? a.cost < b.cost : a.h < b.h;
    });
    return kids;
  }

  SearchResult finish(const Node& n, SearchResult& res) {
    for (uint32_t p : n.parts) res.parts.push_back(arena_[p]);
    res.cost = n.cost;
    res.g = n.g;
    res.h = n.h;
    return res;
  }

  const SearchInput& in_;
  Objective obj_;
  std::vector<PartAnalysis> arena_;
  std::unordered_map<uint64_t, std::vector<uint32_t>> by_hash_;
  std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> splits_;
  std::unordered_map<uint32_t, uint32_t> pool_index_;
  uint64_t seq_ = 0;
};

}  // namespace

SearchResult search(const SearchInput& in, const PartAnalysis& root) { return Search(in, root).run(); }

}  // namespace mc
