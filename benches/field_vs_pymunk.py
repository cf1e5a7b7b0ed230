"""Simulated tracker frames per second on one core: polymimic's field (rapier2d, in Rust) against
the same scene built in pymunk (Chipmunk, driven from Python); then the thread scaling of batch
recording. Run: ``python benches/field_vs_pymunk.py``.

The scene, on both sides: the large field (1020 × 810 mm, no walls: an episode ends when the
ball's centre crosses a line or the robot's centre leaves the field, as in polymimic), a 100 mm
ball (damping 0.4/s, restitution 0.6, rotation locked, a small random wander of its rolling
direction), the 140 × 150 mm Lego robot as a kinematic box driven pose by pose by the
differential-drive model (nominal wheel speeds per primitive, random traction drawn at each
command onset, first-order lag of 0.12 s on speed and 0.02 s on turn rate), two solver
iterations, 240 Hz physics (8 steps per tracker frame), a 30 Hz tracker with Gaussian jitter,
and one scripted primitive per second. Contact materials are set so that the combined
restitution and friction equal rapier's (it averages the two shapes' coefficients, Chipmunk
multiplies them). Both let a resting ball sleep (pymunk through Chipmunk's sleeping). polymimic
also skips rapier's solver whenever the robot cannot touch the ball within a step (their gap is
over 10 mm): it then moves a rolling ball itself by the same damping law; pymunk steps its
solver every time, as Chipmunk offers nothing alike.

Each row counts the frames actually simulated (an episode that ends early is not padded).
"""

import os

os.environ["RAYON_NUM_THREADS"] = "1"  # one thread for ours; must be set before the import
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # no idle BLAS threads spinning on the other core
os.environ.setdefault("OMP_NUM_THREADS", "1")

import argparse  # noqa: E402
import math  # noqa: E402
import random  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import polymimic  # noqa: E402

FIELD_LENGTH_MM, FIELD_WIDTH_MM, BALL_DIAMETER_MM = 1020.0, 810.0, 100.0
ROBOT_LENGTH_MM, ROBOT_WIDTH_MM, WHEEL_BASE_MM = 140.0, 150.0, 175.0
TAU_LINEAR_S, TAU_ANGULAR_S = 0.12, 0.02
# Nominal (left, right) wheel speeds, mm/s, and traction (common sd, differential sd), per primitive.
WHEELS_MM_S = {"forward": (51.55, 47.86), "backward": (-61.45, -54.21), "left": (-43.0, 53.2),
               "right": (51.08, -42.9), "stop": (0.0, 0.0)}
TRACTION = {"forward": (0.29, 0.008), "backward": (0.248, 0.343), "left": (0.65, 0.069),
            "right": (0.294, 0.055), "stop": (0.0, 0.0)}
DAMPING_PER_S, RESTITUTION, BALL_FRICTION, ROBOT_FRICTION, WOBBLE_RAD_PER_SQRT_S = 0.4, 0.6, 0.3, 0.5, 0.35
FRAME_DT_S, SUBSTEPS, TIME_LIMIT_S = 1 / 30, 8, 60.0
POSITION_SIGMA_MM, HEADING_SIGMA_RAD, SPIKE_PROBABILITY, SPIKE_MAX_RAD = 0.3, math.radians(3), 0.01, math.radians(15)
# One primitive a second: approach, push, turn, back off: 30 s in all.
SCRIPT = [p for letter in "FFFFFFLFRFFFFBSFFFFLFFRFFFFFFF"
          for p in [{"F": "forward", "B": "backward", "L": "left", "R": "right", "S": "stop"}[letter]] * 30]


class PymunkEpisode:
    """Configuration 1 of the field in pymunk, stepped one tracker frame at a time."""

    def __init__(self, seed):
        import pymunk

        self.rng = random.Random(seed)
        self.space = space = pymunk.Space()
        space.gravity = (0.0, 0.0)
        space.iterations = 2
        space.damping = math.exp(-DAMPING_PER_S)  # velocity kept per second (only the ball is dynamic)
        space.sleep_time_threshold = 0.5
        space.idle_speed_threshold = 1.0
        self.dt_s = FRAME_DT_S / SUBSTEPS
        sixth = FIELD_LENGTH_MM / 6
        radius = BALL_DIAMETER_MM / 2
        mass = math.pi * radius**2 * 1e-3
        self.ball = pymunk.Body(mass, math.inf)
        self.ball.position = (sixth, 0.0)
        ball_shape = pymunk.Circle(self.ball, radius)
        ball_shape.elasticity, ball_shape.friction = RESTITUTION, BALL_FRICTION
        self.robot = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
        self.robot.position, self.robot.angle = (-sixth, 0.0), 0.0
        corner = 0.1 * min(ROBOT_LENGTH_MM, ROBOT_WIDTH_MM) / 2
        robot_shape = pymunk.Poly.create_box(self.robot, (ROBOT_LENGTH_MM - 2 * corner, ROBOT_WIDTH_MM - 2 * corner),
                                             radius=corner)
        # Chipmunk multiplies the two coefficients, rapier averages them: match rapier's result.
        robot_shape.elasticity = (RESTITUTION + 0.0) / 2 / RESTITUTION
        robot_shape.friction = (BALL_FRICTION + ROBOT_FRICTION) / 2 / BALL_FRICTION
        space.add(self.ball, ball_shape, self.robot, robot_shape)
        self.x, self.y, self.theta = -sixth, 0.0, 0.0
        self.v, self.omega, self.target_v, self.target_omega = 0.0, 0.0, 0.0, 0.0
        self.command, self.held = None, 0
        self.t_s, self.steps, self.outcome = 0.0, 0, None
        self.frames = []
        self.wobble_rad = WOBBLE_RAD_PER_SQRT_S * math.sqrt(self.dt_s)
        self.a_v = 1 - math.exp(-self.dt_s / TAU_LINEAR_S)
        self.a_w = 1 - math.exp(-self.dt_s / TAU_ANGULAR_S)
        self.pending = self.measure()

    def measure(self):
        g, u = self.rng.gauss, self.rng.random
        theta = self.theta + HEADING_SIGMA_RAD * g(0, 1)
        if u() < SPIKE_PROBABILITY:
            theta += math.copysign(SPIKE_MAX_RAD * (1 + 2 * u()) / 3, u() - 0.5)
        bx, by = self.ball.position
        return (self.x + POSITION_SIGMA_MM * g(0, 1), self.y + POSITION_SIGMA_MM * g(0, 1),
                math.remainder(theta, math.tau), bx + POSITION_SIGMA_MM * g(0, 1), by + POSITION_SIGMA_MM * g(0, 1))

    def drive(self, command):
        if command != self.command or self.held >= 30:
            left, right = WHEELS_MM_S[command]
            common_sd, diff_sd = TRACTION[command]
            common = max(1 + common_sd * self.rng.gauss(0, 1), 0.0)
            diff = diff_sd * self.rng.gauss(0, 1)
            left, right = left * common * (1 - diff), right * common * (1 + diff)
            self.target_v, self.target_omega = (left + right) / 2, (right - left) / WHEEL_BASE_MM
            self.command, self.held = command, 0
        self.held += 1

    def step(self, command):
        self.drive(command)
        self.frames.append((self.t_s, *self.pending, command))
        # Written for speed, as a pymunk user would: locals, one read of the ball per step.
        dt, half_l, half_w, mouth = self.dt_s, FIELD_LENGTH_MM / 2, FIELD_WIDTH_MM / 2, FIELD_WIDTH_MM / 4
        cos, sin, gauss, remainder, tau = math.cos, math.sin, self.rng.gauss, math.remainder, math.tau
        robot, ball, space = self.robot, self.ball, self.space
        a_v, a_w, target_v, target_omega, wobble = self.a_v, self.a_w, self.target_v, self.target_omega, self.wobble_rad
        x, y, theta, v, omega = self.x, self.y, self.theta, self.v, self.omega
        bx0, by0 = ball.position
        for _ in range(SUBSTEPS):
            # The motor model moves the true pose; the kinematic body is sent there over the step.
            v += a_v * (target_v - v)
            omega += a_w * (target_omega - omega)
            mid = theta + 0.5 * omega * dt
            dx, dy = v * cos(mid) * dt, v * sin(mid) * dt
            robot.velocity = (dx / dt, dy / dt)
            robot.angular_velocity = omega
            x, y, theta = x + dx, y + dy, remainder(theta + omega * dt, tau)
            space.step(dt)
            if not ball.is_sleeping:
                vx, vy = ball.velocity
                if vx * vx + vy * vy > 1.0:
                    turn = wobble * gauss(0.0, 1.0)
                    c, s = cos(turn), sin(turn)
                    ball.velocity = (c * vx - s * vy, s * vx + c * vy)
            bx, by = ball.position
            if abs(bx) > half_l:
                f = (math.copysign(half_l, bx) - bx0) / (bx - bx0)
                inside = abs(by0 + f * (by - by0)) <= mouth
                self.outcome = ("goal" if bx > 0 else "own_goal") if inside else "ball_out"
            elif abs(by) > half_w:
                self.outcome = "ball_out"
            elif abs(x) > half_l or abs(y) > half_w:
                self.outcome = "robot_out"
            if self.outcome:
                break
            bx0, by0 = bx, by
        self.x, self.y, self.theta, self.v, self.omega = x, y, theta, v, omega
        self.steps += 1
        self.t_s = self.steps * FRAME_DT_S
        if self.outcome is None and self.t_s >= TIME_LIMIT_S - 1e-9:
            self.outcome = "time_up"
        self.pending = self.measure()
        if self.outcome:
            self.frames.append((self.t_s, *self.pending, command))
        return self.outcome

    def run(self, commands):
        for command in commands:
            if self.step(command):
                break
        return self.frames, self.outcome


def frames_per_second(make_and_run, episodes, repeats):
    """Best-of-``repeats`` rate of simulated frames, and the outcomes of the last repeat."""
    best = 0.0
    for _ in range(repeats):
        start = time.perf_counter()
        results = [make_and_run(seed) for seed in range(episodes)]
        elapsed = time.perf_counter() - start
        best = max(best, sum(len(frames) for frames, _ in results) / elapsed)
    return best, results


def ours(seed):
    return polymimic.Episode("lego", configuration=1, seed=seed).run(SCRIPT)


def pymunk_scene(seed):
    return PymunkEpisode(seed).run(SCRIPT)


def pymunk_physics_only(episodes):
    """pymunk's ``space.step`` alone (the robot pushing the ball all along), per 8 steps."""
    import pymunk

    space = pymunk.Space()
    space.iterations = 2
    ball = pymunk.Body(math.pi * 50**2 * 1e-3, math.inf)
    ball.position = (0.0, 0.0)
    robot = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    robot.position = (-120.0, 0.0)
    robot.velocity = (40.0, 0.0)
    space.add(ball, pymunk.Circle(ball, 50), robot, pymunk.Poly.create_box(robot, (140, 150)))
    steps = len(SCRIPT) * SUBSTEPS * episodes
    start = time.perf_counter()
    for _ in range(steps):
        space.step(FRAME_DT_S / SUBSTEPS)
    return len(SCRIPT) * episodes / (time.perf_counter() - start)


RECORD = """
import sys, time, polymimic
best = float("inf")
for _ in range(int(sys.argv[2])):
    start = time.perf_counter()
    polymimic.record("expert", configuration=2, n=int(sys.argv[1]))
    best = min(best, time.perf_counter() - start)
print(best)
"""


def record_seconds(threads, n, repeats):
    """Best time of ``record("expert", configuration=2, n=n)`` in a fresh process with ``threads``."""
    env = {**os.environ, "RAYON_NUM_THREADS": str(threads)}
    out = subprocess.run([sys.executable, "-c", RECORD, str(n), str(repeats)], env=env, check=True,
                         capture_output=True, text=True)
    return float(out.stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--episodes", type=int, default=20, help="scripted episodes per timing run")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--record-n", type=int, default=50)
    args = parser.parse_args()

    import pymunk

    print(f"{args.episodes} episodes of a {len(SCRIPT) // 30} s primitive script, configuration 1, "
          f"{SUBSTEPS * 30} Hz physics, one core; best of {args.repeats}")
    ours_fps, ours_results = frames_per_second(ours, args.episodes, args.repeats)
    peer_fps, peer_results = frames_per_second(pymunk_scene, args.episodes, args.repeats)
    physics_fps = max(pymunk_physics_only(args.episodes) for _ in range(args.repeats))
    print(f"\n{'simulator':<44} {'frames/s':>10} {'frames':>8}  outcomes")
    for name, fps, results in ((f"polymimic {polymimic.__version__} (rapier2d, Episode.run)", ours_fps, ours_results),
                               (f"pymunk {pymunk.version} (Chipmunk {pymunk.chipmunk_version[:5]}, same scene)",
                                peer_fps, peer_results)):
        outcomes = {}
        for _, outcome in results:
            outcomes[outcome] = outcomes.get(outcome, 0) + 1
        frames = sum(len(f) for f, _ in results)
        print(f"{name:<44} {fps:>10,.0f} {frames:>8}  "
              + ", ".join(f"{k or 'running'} {v}" for k, v in sorted(outcomes.items(), key=str)))
    print(f"{'pymunk space.step alone, robot pushing ball':<44} {physics_fps:>10,.0f} {'':>8}  "
          "(no motor, tracker or rules)")
    print(f"\nours / pymunk: {ours_fps / peer_fps:.1f}x (target ≥ 5x); "
          f"ours / pymunk's physics alone: {ours_fps / physics_fps:.1f}x")

    print(f"\nrecord('expert', configuration=2, n={args.record_n}), fresh process, best of {args.repeats}")
    print(f"{'threads':>7} {'seconds':>9} {'speed-up':>9}")
    one = record_seconds(1, args.record_n, args.repeats)
    print(f"{1:>7} {one:>9.3f} {1.0:>8.2f}x")
    for threads in range(2, (os.cpu_count() or 1) + 1):
        seconds = record_seconds(threads, args.record_n, args.repeats)
        print(f"{threads:>7} {seconds:>9.3f} {one / seconds:>8.2f}x")


if __name__ == "__main__":
    main()
