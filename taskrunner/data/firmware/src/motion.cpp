#include "motion.h"

namespace trs {

const char* mode_name(Mode mode) {
  switch (mode) {
    case Mode::kIdle: return "idle";
    case Mode::kMove: return "move";
    case Mode::kTraj: return "traj";
  }
  return "idle";
}

int32_t lerp_centi(int32_t a, int32_t b, uint32_t num, uint32_t den) {
  const int64_t delta = static_cast<int64_t>(b) - a;
  const int64_t scaled = delta * static_cast<int64_t>(num);
  const int64_t half = den / 2;
  const int64_t step = scaled >= 0 ? (scaled + half) / den : -((-scaled + half) / den);
  return static_cast<int32_t>(a + step);
}

Motion::Motion(const Config& config)
    // Clamped so a bad config cannot index past the arrays (check_config reports it).
    : n_(config.n_servos < 0 ? 0 : config.n_servos > kMaxServos ? kMaxServos : config.n_servos),
      tick_ms_(config.tick_ms == 0 ? 1 : config.tick_ms),
      speed_(config.default_speed) {
  for (int i = 0; i < n_; ++i) pos_[i] = config.servos[i].home_cdeg;
  move_target_ = pos_;
  segment_start_ = pos_;
}

void Motion::clear_queue() {
  head_ = 0;
  count_ = 0;
  queued_ms_ = 0;
  segment_elapsed_ms_ = 0;
}

void Motion::pop_front() {
  queued_ms_ -= queue_[head_].dt_ms;
  head_ = (head_ + 1) % kQueueCapacity;
  --count_;
}

void Motion::move_to(const Angles& target) {
  clear_queue();
  powered_ = true;
  move_target_ = pos_;
  for (int i = 0; i < n_; ++i) move_target_[i] = target[i];
  mode_ = Mode::kMove;
  bool reached = true;
  for (int i = 0; i < n_; ++i) reached = reached && pos_[i] == move_target_[i];
  if (reached) mode_ = Mode::kIdle;
}

bool Motion::push_point(uint32_t dt_ms, const Angles& angles) {
  if (count_ >= kQueueCapacity) return false;
  if (mode_ != Mode::kTraj) {
    clear_queue();
    segment_start_ = pos_;
    mode_ = Mode::kTraj;
  }
  powered_ = true;
  Point& slot = queue_[(head_ + count_) % kQueueCapacity];
  slot.dt_ms = dt_ms;
  slot.angles = pos_;
  for (int i = 0; i < n_; ++i) slot.angles[i] = angles[i];
  ++count_;
  queued_ms_ += dt_ms;
  return true;
}

void Motion::stop() {
  clear_queue();
  move_target_ = pos_;
  segment_start_ = pos_;
  mode_ = Mode::kIdle;
}

void Motion::set_speed(int degrees_per_tick) { speed_ = degrees_per_tick; }

const Angles& Motion::target() const {
  switch (mode_) {
    case Mode::kMove: return move_target_;
    case Mode::kTraj: return queue_[(head_ + count_ - 1) % kQueueCapacity].angles;
    case Mode::kIdle: break;
  }
  return pos_;
}

uint32_t Motion::buffered_ms() const {
  return mode_ == Mode::kTraj ? queued_ms_ - segment_elapsed_ms_ : 0;
}

void Motion::tick() {
  ++ticks_;
  if (mode_ == Mode::kMove) {
    const int32_t step = speed_ * 100;
    bool reached = true;
    for (int i = 0; i < n_; ++i) {
      const int32_t diff = move_target_[i] - pos_[i];
      if (diff > step) {
        pos_[i] += step;
      } else if (diff < -step) {
        pos_[i] -= step;
      } else {
        pos_[i] = move_target_[i];
      }
      reached = reached && pos_[i] == move_target_[i];
    }
    if (reached) mode_ = Mode::kIdle;
  } else if (mode_ == Mode::kTraj) {
    segment_elapsed_ms_ += tick_ms_;
    // Points shorter than a tick are passed through: time carries over, so the
    // servos stay on the timeline rather than on the tick grid.
    while (count_ > 0 && segment_elapsed_ms_ >= front().dt_ms) {
      segment_elapsed_ms_ -= front().dt_ms;
      segment_start_ = front().angles;
      pop_front();
    }
    if (count_ == 0) {
      // Drained: hold the last point. A late point starts a new timeline from here.
      pos_ = segment_start_;
      move_target_ = pos_;
      segment_elapsed_ms_ = 0;
      mode_ = Mode::kIdle;
    } else {
      const Point& next = front();
      for (int i = 0; i < n_; ++i) {
        pos_[i] = lerp_centi(segment_start_[i], next.angles[i], segment_elapsed_ms_,
                             next.dt_ms);
      }
    }
  }
}

}  // namespace trs
