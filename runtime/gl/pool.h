// GL objects handed out again once idle (pooled_buffer, pooled_target): the pool holds a reference
// to each, and one is idle when that is the only reference left. Reusing them spares llvmpipe
// allocating and zeroing storage for every view of a dataset or every frame.
#pragma once
#include <memory>
#include <vector>

namespace sn::gl {

template <class T>
class Pool {
 public:
  explicit Pool(int idle_max) : idle_max_(idle_max) {}

  // An idle object that `fits`, the first one `better` prefers (better(a, b): a over b), or
  // `make()`'s new one, with room kept for it when it comes back: at most idle_max idle in all.
  template <class Fits, class Better, class Make>
  std::shared_ptr<T> take(const Fits& fits, const Better& better, const Make& make) {
    std::shared_ptr<T> best;
    for (auto& t : items_)
      if (t.use_count() == 1 && fits(*t) && (!best || better(*t, *best))) best = t;
    if (best) return best;
    auto made = make();
    int idle = 0;
    for (auto& t : items_) idle += t.use_count() == 1;
    for (auto it = items_.begin(); idle > idle_max_ - 1 && it != items_.end();) {
      if (it->use_count() == 1) {
        it = items_.erase(it);
        --idle;
      } else {
        ++it;
      }
    }
    items_.push_back(made);
    return made;
  }
  void clear() { items_.clear(); }

 private:
  int idle_max_;
  std::vector<std::shared_ptr<T>> items_;
};

}  // namespace sn::gl
