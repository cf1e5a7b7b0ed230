"""Tracker logs the tracks tests write: a CSV of readings, and readings moving steadily."""

HEADER = "t_s,robot_x_mm,robot_y_mm,robot_theta_rad,ball_x_mm,ball_y_mm"


def _csv(tmp_path, rows, header=HEADER, name="log.csv"):
    path = tmp_path / name
    path.write_text(header + "\n" + "".join(",".join(map(str, row)) + "\n" for row in rows))
    return path


def _readings(n, *, robot=(-170.0, 0.0), ball=(170.0, 0.0), ball_step=(0.0, 0.0), robot_step=(0.0, 0.0),
              start_s=0.0):
    """n readings 1/30 s apart, robot and ball moving by a fixed step per reading."""
    return [[start_s + i / 30, robot[0] + i * robot_step[0], robot[1] + i * robot_step[1], 0.0,
             ball[0] + i * ball_step[0], ball[1] + i * ball_step[1]] for i in range(n)]
