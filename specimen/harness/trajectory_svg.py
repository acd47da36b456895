"""Draws one flight: the planned route, the track before the checkpoint, the outage, the track
after the resume, and the checkpoint and resume points."""
import csv
import math

EARTH_RADIUS = 6378100.0


def _route_ne(mission_items):
    """North/east metres of home and the route points (waypoints, positioned LANDs)."""
    home = mission_items[0]
    scale = math.cos(math.radians(home["lat"]))
    def ne(item):
        return ((item["lat"] - home["lat"]) * math.radians(1) * EARTH_RADIUS,
                (item["lng"] - home["lng"]) * math.radians(1) * EARTH_RADIUS * scale)
    points = [ne(i) for i in mission_items[1:]
              if i["command"] == 16 or (i["command"] == 21 and (i["lat"] or i["lng"]))]
    return (0.0, 0.0), points


def read_mission(path):
    items = []
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#") or line.startswith("QGC WPL"):
                continue
            c = line.split()
            items.append({"command": int(c[3]), "lat": float(c[8]), "lng": float(c[9])})
    return items


def read_track(path):
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            rows.append((float(r["north"]), float(r["east"]), int(r["segment"])))
    return rows


CHAR_WIDTH = 7.0  # px per character of the 12 px sans-serif labels, a little generous
TEXT_HEIGHT = 12.0


def text_box(x, y, text):
    """The box (left, top, right, bottom) a label drawn at baseline (x, y) covers."""
    return (x, y - TEXT_HEIGHT + 1, x + CHAR_WIDTH * len(text), y + 3)


def overlaps(a, b):
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def place_label(x, y, text, occupied, width):
    """A baseline for `text` next to the point (x, y), as near as it goes without covering a
    box of `occupied` or leaving the picture: to the right first, then to the left, further
    up or down each time."""
    label_width = CHAR_WIDTH * len(text)
    candidates = []
    for dy in (4, -12, 20, -28, 36, -44, 52, -60, 68, -76, 84, -92):
        candidates += [(x + 10, y + dy), (x - 10 - label_width, y + dy)]
    for tx, ty in candidates:
        box = text_box(tx, ty, text)
        if box[0] >= 0 and box[2] <= width and box[1] >= 24 and not any(
                overlaps(box, other) for other in occupied):
            return tx, ty
    return candidates[0]


def draw(mission_path, track_path, flight, title, out_path, size=720):
    home, route = _route_ne(read_mission(mission_path))
    track = read_track(track_path)
    xs = [p[1] for p in route + [home]] + [t[1] for t in track]
    ys = [p[0] for p in route + [home]] + [t[0] for t in track]
    span = max(max(xs) - min(xs), max(ys) - min(ys), 1.0)
    margin = 60
    scale = (size - 2 * margin) / span
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2

    def xy(north, east):  # east right, north up
        return (size / 2 + (east - cx) * scale, size / 2 - (north - cy) * scale)

    def polyline(points, style):
        if len(points) < 2:
            return ""
        coords = " ".join("%.1f,%.1f" % xy(n, e) for n, e in points)
        return '<polyline points="%s" %s fill="none"/>\n' % (coords, style)

    svg = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" '
           'font-size="12">\n' % (size, size + 48),
           '<rect width="100%" height="100%" fill="white"/>\n',
           '<text x="10" y="20" font-size="14">%s</text>\n' % title]
    svg.append(polyline(route, 'stroke="#999" stroke-width="2" stroke-dasharray="6,4"'))
    occupied = []  # the boxes of the labels drawn so far
    for i, (n, e) in enumerate(route):
        x, y = xy(n, e)
        svg.append('<circle cx="%.1f" cy="%.1f" r="4" fill="#999"/>'
                   '<text x="%.1f" y="%.1f" fill="#666">%d</text>\n' % (x, y, x + 6, y - 6, i + 1))
        occupied.append(text_box(x + 6, y - 6, str(i + 1)))
    hx, hy = xy(*home)
    svg.append('<rect x="%.1f" y="%.1f" width="8" height="8" fill="black"/>'
               '<text x="%.1f" y="%.1f">home</text>\n' % (hx - 4, hy - 4, hx + 8, hy + 12))
    occupied.append(text_box(hx + 8, hy + 12, "home"))
    colours = {0: 'stroke="#1f77b4" stroke-width="2"', 1: 'stroke="#d62728" stroke-width="3"',
               2: 'stroke="#2ca02c" stroke-width="2"'}
    for segment in (0, 1, 2):
        # Each piece starts where the previous one ended, so the track stays continuous.
        first = next((i for i, t in enumerate(track) if t[2] == segment), None)
        if first is None:
            continue
        points = [(n, e) for n, e, s in track[first:] if s == segment]
        if first > 0:
            points.insert(0, track[first - 1][:2])
        svg.append(polyline(points, colours[segment]))
    # The points are often close together and near a waypoint: each label goes where it covers
    # no waypoint's number and no other label, joined to its point by a line when moved away.
    for key, colour, label in (("checkpoint_point", "#1f77b4", "checkpoint"),
                               ("resume_point", "#2ca02c", "resume"),
                               ("exploit_point", "#d62728", "exploit")):
        p = flight.get(key)
        if p:
            x, y = xy(p["north"], p["east"])
            text = "%s (t=%.1f s)" % (label, p["t"])
            tx, ty = place_label(x, y, text, occupied, size)
            occupied.append(text_box(tx, ty, text))
            svg.append('<circle cx="%.1f" cy="%.1f" r="7" fill="none" stroke="%s" stroke-width="3"/>'
                       % (x, y, colour))
            if abs(ty - 4 - y) > 8:
                near_x = tx if tx > x else tx + CHAR_WIDTH * len(text)
                svg.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="%s" '
                           'stroke-width="1"/>' % (x, y, near_x, ty - 4, colour))
            svg.append('<text x="%.1f" y="%.1f" fill="%s">%s</text>\n' % (tx, ty, colour, text))
    legend = [("#999", "planned route"), ("#1f77b4", "flown before the checkpoint (V0)"),
              ("#d62728", "autopilot down (motors hold)"), ("#2ca02c", "flown after the resume")]
    for i, (colour, text) in enumerate(legend):
        y = size - 8 + 16 * (i // 2)
        x = 10 + 300 * (i % 2)
        svg.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="%s" stroke-width="3"/>'
                   '<text x="%d" y="%d">%s</text>\n' % (x, y, x + 20, y, colour, x + 24, y + 4, text))
    svg.append('<text x="10" y="%d" fill="#666">%s</text>\n' % (size + 38, "%.0f m across; result: %s"
                                                                % (span, flight.get("reason", ""))))
    svg.append("</svg>\n")
    with open(out_path, "w") as f:
        f.write("".join(svg))
