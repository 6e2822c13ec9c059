#include <cmath>
#include <cstdlib>
#include <random>
#include <vector>

#include "../src/motion.h"
#include "harness.h"
#include "helpers.h"

using th::angles6;
using trs::Angles;
using trs::Mode;
using trs::Motion;

namespace {

trs::Config arm() { return trs::servo_arm_config(); }

Angles all(int32_t c) { return angles6(c, c, c, c, c, c); }

// A timeline for checking trajectory mode against: point k at time t_k (ms, from the
// origin), starting at `start` at t = 0. Linear interpolation in double precision.
struct Timeline {
  Angles start{};
  std::vector<double> times;
  std::vector<Angles> points;

  double at(double t, int servo) const {
    double t0 = 0;
    double a0 = start[servo];
    for (std::size_t k = 0; k < times.size(); ++k) {
      if (t <= times[k]) {
        const double s = (t - t0) / (times[k] - t0);
        return a0 + s * (points[k][servo] - a0);
      }
      t0 = times[k];
      a0 = points[k][servo];
    }
    return a0;
  }
  double end() const { return times.empty() ? 0 : times.back(); }
};

// Largest |pos - timeline| (centidegrees) over every tick until the timeline ends,
// pushing all points first.
int32_t worst_error(Motion& motion, const Timeline& timeline, const std::vector<uint32_t>& dts) {
  for (std::size_t k = 0; k < dts.size(); ++k) {
    if (!motion.push_point(dts[k], timeline.points[k])) return 1 << 30;
  }
  int32_t worst = 0;
  const uint32_t tick_ms = motion.tick_ms();
  for (uint32_t j = 1; j * tick_ms <= timeline.end() + 3 * tick_ms; ++j) {
    motion.tick();
    for (int i = 0; i < motion.n_servos(); ++i) {
      const double expected = timeline.at(static_cast<double>(j) * tick_ms, i);
      const auto error =
          static_cast<int32_t>(std::ceil(std::fabs(motion.pos()[i] - expected) - 1e-9));
      if (error > worst) worst = error;
    }
  }
  return worst;
}

Timeline timeline_from(const Angles& start, const std::vector<uint32_t>& dts,
                       const std::vector<Angles>& points) {
  Timeline timeline;
  timeline.start = start;
  double t = 0;
  for (std::size_t k = 0; k < dts.size(); ++k) {
    t += dts[k];
    timeline.times.push_back(t);
    timeline.points.push_back(points[k]);
  }
  return timeline;
}

}  // namespace

TEST(motion_boots_idle_unpowered_at_home) {
  Motion motion(arm());
  CHECK(motion.mode() == Mode::kIdle);
  CHECK(!motion.moving());
  CHECK(!motion.powered());
  CHECK(motion.pos() == all(9000));
  CHECK(motion.target() == all(9000));
  CHECK_EQ(motion.speed(), 5);
  CHECK_EQ(motion.ticks(), 0u);
  motion.tick();
  CHECK_EQ(motion.ticks(), 1u);
  CHECK(motion.pos() == all(9000));
}

TEST(stepping_moves_speed_degrees_per_tick_at_every_speed) {
  for (int speed = trs::kSpeedMin; speed <= trs::kSpeedMax; ++speed) {
    Motion motion(arm());
    motion.set_speed(speed);
    motion.move_to(angles6(18000, 0, 9000 + 1234, 9000 - 1, 0, 18000));
    CHECK(motion.powered());
    CHECK(motion.mode() == Mode::kMove);
    int ticks = 0;
    while (motion.moving() && ticks < 1000) {
      const Angles before = motion.pos();
      motion.tick();
      ++ticks;
      for (int i = 0; i < 6; ++i) {
        const int32_t moved = std::abs(motion.pos()[i] - before[i]);
        const int32_t left_before = std::abs(motion.target()[i] - before[i]);
        // Exactly `speed` degrees, or the remainder on the last step.
        const int32_t expected = left_before < speed * 100 ? left_before : speed * 100;
        if (moved != expected) {
          CHECK_EQ(moved, expected);
          return;
        }
      }
    }
    // 90 degrees at `speed` per tick takes ceil(90 / speed) ticks.
    CHECK_EQ(ticks, (90 + speed - 1) / speed);
    CHECK(motion.pos() == angles6(18000, 0, 10234, 8999, 0, 18000));
    CHECK(motion.mode() == Mode::kIdle);
  }
}

TEST(stepping_servos_move_independently) {
  Motion motion(arm());
  motion.set_speed(10);
  motion.move_to(angles6(9000 + 1000, 9000 + 2000, 9000, 9000 - 1500, 9000, 9000));
  motion.tick();
  CHECK(motion.pos() == angles6(10000, 10000, 9000, 8000, 9000, 9000));
  CHECK(motion.moving());
  motion.tick();
  CHECK(motion.pos() == angles6(10000, 11000, 9000, 7500, 9000, 9000));
  CHECK(!motion.moving());
  CHECK(motion.mode() == Mode::kIdle);
}

TEST(speed_change_applies_from_the_next_tick) {
  Motion motion(arm());
  motion.set_speed(1);
  motion.move_to(all(18000));
  motion.tick();
  CHECK(motion.pos() == all(9100));
  motion.set_speed(20);
  motion.tick();
  CHECK(motion.pos() == all(11100));
}

TEST(a_new_move_retargets_from_the_current_position) {
  Motion motion(arm());
  motion.move_to(all(18000));
  motion.tick();
  CHECK(motion.pos() == all(9500));
  motion.move_to(all(0));
  motion.tick();
  CHECK(motion.pos() == all(9000));
}

TEST(move_to_the_current_position_is_idle_at_once) {
  Motion motion(arm());
  motion.move_to(all(9000));
  CHECK(motion.mode() == Mode::kIdle);
  CHECK(motion.powered());
}

TEST(stop_halts_a_move_where_it_is) {
  Motion motion(arm());
  motion.move_to(all(18000));
  motion.tick();
  motion.tick();
  motion.stop();
  CHECK(motion.mode() == Mode::kIdle);
  CHECK(motion.pos() == all(10000));
  CHECK(motion.target() == all(10000));
  motion.tick();
  CHECK(motion.pos() == all(10000));
  CHECK(motion.powered());
}

TEST(lerp_centi_rounds_half_away_from_zero) {
  CHECK_EQ(trs::lerp_centi(0, 100, 1, 2), 50);
  CHECK_EQ(trs::lerp_centi(0, 1, 1, 2), 1);
  CHECK_EQ(trs::lerp_centi(0, -1, 1, 2), -1);
  CHECK_EQ(trs::lerp_centi(100, 0, 1, 3), 67);
  CHECK_EQ(trs::lerp_centi(0, 18000, 0, 80), 0);
  CHECK_EQ(trs::lerp_centi(0, 18000, 80, 80), 18000);
}

TEST(trajectory_on_the_tick_grid_hits_every_point) {
  Motion motion(arm());
  for (int k = 1; k <= 10; ++k) CHECK(motion.push_point(80, all(9000 + 100 * k)));
  CHECK(motion.mode() == Mode::kTraj);
  CHECK_EQ(motion.queued(), 10);
  CHECK_EQ(motion.buffered_ms(), 800u);
  CHECK(motion.target() == all(10000));
  for (int k = 1; k <= 10; ++k) {
    motion.tick();
    CHECK(motion.pos() == all(9000 + 100 * k));
    CHECK_EQ(motion.queued(), 10 - k);
  }
  CHECK(motion.mode() == Mode::kIdle);
  CHECK_EQ(motion.buffered_ms(), 0u);
  motion.tick();
  CHECK(motion.pos() == all(10000));
}

TEST(trajectory_positions_match_the_timeline_at_every_tick) {
  // Segment lengths off the tick grid, shorter than a tick, and long ones.
  const std::vector<uint32_t> dts = {80, 37, 200, 1, 55, 160, 123, 80, 999, 5, 5, 5, 240};
  std::vector<Angles> points;
  std::mt19937 rng(1234);
  std::uniform_int_distribution<int32_t> angle(0, 18000);
  for (std::size_t k = 0; k < dts.size(); ++k) {
    Angles a{};
    for (int i = 0; i < 6; ++i) a[i] = angle(rng);
    points.push_back(a);
  }
  Motion motion(arm());
  const Timeline timeline = timeline_from(motion.pos(), dts, points);
  CHECK(worst_error(motion, timeline, dts) <= 1);  // 0.01 degree (rounding)
  CHECK(motion.pos() == points.back());
  CHECK(motion.mode() == Mode::kIdle);
}

TEST(trajectory_follows_random_timelines_within_a_hundredth_of_a_degree) {
  std::mt19937 rng(42);
  std::uniform_int_distribution<int32_t> angle(0, 18000);
  std::uniform_int_distribution<uint32_t> dt(1, 400);
  for (int trial = 0; trial < 50; ++trial) {
    trs::Config config = arm();
    config.tick_ms = trial % 2 ? 80 : 20 + static_cast<uint32_t>(trial);
    Motion motion(config);
    std::vector<uint32_t> dts;
    std::vector<Angles> points;
    for (int k = 0; k < 40; ++k) {
      dts.push_back(dt(rng));
      Angles a{};
      for (int i = 0; i < 6; ++i) a[i] = angle(rng);
      points.push_back(a);
    }
    const Timeline timeline = timeline_from(motion.pos(), dts, points);
    const int32_t worst = worst_error(motion, timeline, dts);
    if (worst > 1) {
      CHECK_EQ(worst, 1);
      return;
    }
  }
}

TEST(trajectory_streamed_a_few_points_ahead_matches_the_timeline) {
  // A host sending a 100 Hz-sampled ramp downsampled to 80 ms, keeping 3 points queued.
  Motion motion(arm());
  const Angles start = motion.pos();
  std::vector<uint32_t> dts;
  std::vector<Angles> points;
  for (int k = 1; k <= 25; ++k) {  // 2 s: 90 -> 150 degrees on every servo
    dts.push_back(80);
    points.push_back(all(9000 + (6000 * k) / 25));
  }
  const Timeline timeline = timeline_from(start, dts, points);
  std::size_t sent = 0;
  int32_t worst = 0;
  for (uint32_t j = 1; j <= 30; ++j) {
    while (sent < dts.size() && motion.queued() < 3) {
      CHECK(motion.push_point(dts[sent], points[sent]));
      ++sent;
    }
    motion.tick();
    for (int i = 0; i < 6; ++i) {
      const double expected = timeline.at(j * 80.0, i);
      const auto error = static_cast<int32_t>(std::ceil(std::fabs(motion.pos()[i] - expected)));
      if (error > worst) worst = error;
    }
  }
  CHECK(worst <= 1);
  CHECK(motion.pos() == all(15000));
}

TEST(trajectory_drains_to_a_hold_and_a_late_point_starts_a_new_timeline) {
  Motion motion(arm());
  motion.push_point(160, all(10000));
  motion.tick();
  CHECK(motion.pos() == all(9500));
  motion.tick();
  CHECK(motion.pos() == all(10000));
  CHECK(motion.mode() == Mode::kIdle);
  motion.tick();
  motion.tick();
  CHECK(motion.pos() == all(10000));
  // The host was late: this point's 80 ms count from the last tick, not from t = 160.
  motion.push_point(80, all(10800));
  CHECK(motion.mode() == Mode::kTraj);
  CHECK_EQ(motion.buffered_ms(), 80u);
  motion.tick();
  CHECK(motion.pos() == all(10800));
}

TEST(trajectory_buffered_ms_counts_down_within_a_segment) {
  Motion motion(arm());
  motion.push_point(200, all(10000));
  motion.push_point(100, all(11000));
  CHECK_EQ(motion.buffered_ms(), 300u);
  motion.tick();
  CHECK_EQ(motion.buffered_ms(), 220u);
  CHECK_EQ(motion.queued(), 2);
  motion.tick();
  motion.tick();  // t = 240: first point passed
  CHECK_EQ(motion.buffered_ms(), 60u);
  CHECK_EQ(motion.queued(), 1);
  CHECK(motion.pos() == all(10400));
}

TEST(trajectory_queue_is_bounded_and_rejects_without_side_effects) {
  Motion motion(arm());
  for (int k = 0; k < trs::kQueueCapacity; ++k) CHECK(motion.push_point(80, all(9000 + k)));
  CHECK_EQ(motion.queued(), trs::kQueueCapacity);
  const uint32_t buffered = motion.buffered_ms();
  CHECK(!motion.push_point(80, all(0)));
  CHECK_EQ(motion.queued(), trs::kQueueCapacity);
  CHECK_EQ(motion.buffered_ms(), buffered);
  CHECK(motion.target() == all(9000 + trs::kQueueCapacity - 1));
  motion.tick();
  CHECK(motion.push_point(80, all(0)));  // one slot free after a tick
  CHECK(!motion.push_point(80, all(0)));
}

TEST(trajectory_queue_wraps_around_many_times) {
  Motion motion(arm());
  int pushed = 0;
  for (int j = 0; j < 1000; ++j) {
    while (motion.queued() < 5) {
      ++pushed;
      CHECK(motion.push_point(80, all(9000 + (pushed % 2) * 100)));
    }
    motion.tick();
  }
  CHECK(motion.mode() == Mode::kTraj);
  CHECK(motion.pos() == all(9000 + ((pushed - 4) % 2) * 100));
}

TEST(stop_mid_trajectory_holds_and_clears_the_queue) {
  Motion motion(arm());
  motion.push_point(400, all(14000));  // 10 degrees per 80 ms tick
  motion.push_point(400, all(9000));
  motion.tick();
  motion.tick();
  CHECK(motion.pos() == all(11000));
  motion.stop();
  CHECK(motion.mode() == Mode::kIdle);
  CHECK_EQ(motion.queued(), 0);
  CHECK_EQ(motion.buffered_ms(), 0u);
  CHECK(motion.target() == all(11000));
  for (int j = 0; j < 20; ++j) motion.tick();
  CHECK(motion.pos() == all(11000));
  // The next point starts a fresh timeline from the stop position.
  motion.push_point(80, all(11800));
  motion.tick();
  CHECK(motion.pos() == all(11800));
}

TEST(move_during_a_trajectory_abandons_the_queue) {
  Motion motion(arm());
  motion.push_point(800, all(17000));
  motion.tick();
  CHECK(motion.pos() == all(9800));
  motion.move_to(all(9000));
  CHECK(motion.mode() == Mode::kMove);
  CHECK_EQ(motion.queued(), 0);
  motion.tick();
  CHECK(motion.pos() == all(9300));
}

TEST(trajectory_during_a_move_starts_from_the_current_position) {
  Motion motion(arm());
  motion.move_to(all(18000));
  motion.tick();  // 95 degrees
  motion.push_point(160, all(9500 + 1000));
  CHECK(motion.mode() == Mode::kTraj);
  CHECK(motion.target() == all(10500));
  motion.tick();
  CHECK(motion.pos() == all(10000));
  motion.tick();
  CHECK(motion.pos() == all(10500));
  motion.tick();
  CHECK(motion.pos() == all(10500));  // the MOVE target is gone
}

TEST(trajectory_ignores_speed) {
  Motion motion(arm());
  motion.set_speed(1);
  motion.push_point(80, all(18000));  // 90 degrees in one tick
  motion.tick();
  CHECK(motion.pos() == all(18000));
}

TEST(motion_works_with_one_and_sixteen_servos) {
  for (int n : {1, 16}) {
    trs::Config config;
    config.n_servos = n;
    for (int i = 0; i < n; ++i) config.servos[i].channel = static_cast<uint8_t>(i);
    REQUIRE(trs::check_config(config).empty());
    Motion motion(config);
    Angles target{};
    for (int i = 0; i < n; ++i) target[i] = 18000;
    motion.move_to(target);
    for (int j = 0; j < 18; ++j) motion.tick();
    CHECK(motion.pos() == target);
    CHECK(!motion.moving());
  }
}

TEST(motion_survives_an_invalid_config) {
  trs::Config config = arm();
  config.n_servos = 99;  // check_config rejects this; Motion must still not overflow
  config.tick_ms = 0;
  Motion motion(config);
  CHECK_EQ(motion.n_servos(), trs::kMaxServos);
  CHECK_EQ(motion.tick_ms(), 1u);
  motion.push_point(5, Angles{});
  for (int j = 0; j < 10; ++j) motion.tick();
  CHECK(motion.pos() == Angles{});
}
