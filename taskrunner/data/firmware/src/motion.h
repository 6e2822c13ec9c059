// The servo state model: where each servo is commanded to be, advanced once per tick.
//
// Two ways to move (see PROTOCOL.md, "Timing"):
//  - step mode (MOVE, HOME, ZERO): every tick each servo moves `speed` degrees toward
//    its target, or the rest of the way if closer; servos move independently.
//  - trajectory mode (TRAJ): a queue of timed points; point k is to be reached dt_k ms
//    after point k-1. Every tick the trajectory clock advances tick_ms and the servos
//    take the linear interpolation between the two points around it. The first point
//    after an empty queue is timed from the last tick (its segment starts at the
//    current positions). When the queue drains the servos hold the last point.
// Positions are exact integer centidegrees, so runs are bit-for-bit reproducible.
#pragma once

#include <cstdint>

#include "config.h"

namespace trs {

enum class Mode : uint8_t { kIdle, kMove, kTraj };

const char* mode_name(Mode mode);  // "idle", "move", "traj"

class Motion {
 public:
  // Starts idle at the home angles, outputs off (servos unpowered), default speed.
  explicit Motion(const Config& config);

  // Step toward `target` at the current speed; clears the trajectory queue; powers on.
  void move_to(const Angles& target);
  // Appends a point reached `dt_ms` after the previous one. False (nothing changes)
  // when the queue is full. Leaving step mode abandons the MOVE target. Powers on.
  bool push_point(uint32_t dt_ms, const Angles& angles);
  // Halt where the servos are now and clear the queue (outputs stay as they are).
  void stop();
  // Degrees per tick in step mode; the caller checks the range.
  void set_speed(int degrees_per_tick);

  // Advance one tick (tick_ms of firmware time).
  void tick();

  Mode mode() const { return mode_; }
  bool moving() const { return mode_ != Mode::kIdle; }
  bool powered() const { return powered_; }
  int n_servos() const { return n_; }
  const Angles& pos() const { return pos_; }
  // Where the motion ends: the MOVE target, the last queued point, or pos when idle.
  const Angles& target() const;
  int speed() const { return speed_; }
  int queued() const { return count_; }
  // Trajectory time left until the last queued point is reached (0 unless kTraj).
  uint32_t buffered_ms() const;
  uint32_t ticks() const { return ticks_; }
  uint32_t tick_ms() const { return tick_ms_; }

 private:
  struct Point {
    uint32_t dt_ms;
    Angles angles;
  };
  const Point& front() const { return queue_[head_]; }
  void pop_front();
  void clear_queue();

  int n_;
  uint32_t tick_ms_;
  Mode mode_ = Mode::kIdle;
  bool powered_ = false;
  int speed_;
  uint32_t ticks_ = 0;
  Angles pos_{};
  Angles move_target_{};
  Angles segment_start_{};     // where the active segment began
  uint32_t segment_elapsed_ms_ = 0;
  uint32_t queued_ms_ = 0;     // sum of dt_ms over the queue
  Point queue_[kQueueCapacity];
  int head_ = 0;
  int count_ = 0;
};

// a + (b - a) * num / den, rounded half away from zero (den > 0, 0 <= num <= den).
int32_t lerp_centi(int32_t a, int32_t b, uint32_t num, uint32_t den);

}  // namespace trs
