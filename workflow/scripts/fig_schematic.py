"""Fig. 1: the problem. Two elastically similar cylinders of radius a pressed end to end by F and
twisted by T (side view), and the interface: stick disc r < b, slip annulus b < r < a (plan view)."""

import numpy as np
from _plotting import figure_parser, save_figure, subplots, use_style
from matplotlib import patches


def side_view(ax):
    """The two cylinders, the loads and the coordinates (lengths in a)."""
    for bottom, shade in ((0.0, "0.85"), (-1.6, "0.75")):
        ax.add_patch(patches.Rectangle((-1.0, bottom), 2.0, 1.6, facecolor=shade, edgecolor="k", lw=1.0))
    ax.plot([-1.0, 1.0], [0.0, 0.0], "k-", lw=2.0)
    ax.plot([0, 0], [-1.9, 1.9], color="0.4", lw=0.6, ls="-.")
    for y0, direction in ((2.25, -1), (-2.25, 1)):  # the normal force F on each far end
        ax.annotate("", xy=(0, y0 + direction * 0.55), xytext=(0, y0),
                    arrowprops={"arrowstyle": "-|>", "lw": 1.4, "color": "k"})
    ax.text(0.12, 2.05, "$F$", fontsize=10)
    ax.text(0.12, -2.2, "$F$", fontsize=10)
    for y0, sense in ((1.35, 1), (-1.35, -1)):  # the torque T about the axis, opposite on the two ends
        arc = patches.FancyArrowPatch((-0.55 * sense, y0), (0.55 * sense, y0), connectionstyle="arc3,rad=0.45",
                                      arrowstyle="-|>", mutation_scale=10, lw=1.2, color="#D55E00")
        ax.add_patch(arc)
    ax.text(0.66, 1.05, "$T$", color="#D55E00", fontsize=10)
    ax.text(0.66, -1.6, "$T$", color="#D55E00", fontsize=10)
    # the coordinate arrows over the thick interface line (drawn under it, only the head of r showed)
    for tip in ((0.6, 0.0), (0.0, 0.6)):
        ax.annotate("", xy=tip, xytext=(0.0, 0.0), zorder=5,
                    arrowprops={"arrowstyle": "-|>", "lw": 1.2, "color": "#0072B2"})
    ax.text(0.62, 0.06, "$r$", fontsize=9)
    ax.text(0.06, 0.62, "$z$", fontsize=9)
    ax.annotate("", xy=(1.0, -1.75), xytext=(0.0, -1.75), arrowprops={"arrowstyle": "<->", "lw": 0.8})
    ax.text(0.45, -1.95, "$a$", fontsize=9)
    ax.text(0.12, -0.3, "$z = 0$", fontsize=8)  # the interface (the thick line), right of the dash-dot axis
    ax.set_xlim(-1.4, 1.4)
    ax.set_ylim(-2.4, 2.4)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title("(a) side view", fontsize=9)


def plan_view(ax, b=0.6):
    """The interface seen along the axis: stick disc and slip annulus."""
    theta = np.linspace(0, 2 * np.pi, 361)
    ax.fill(np.cos(theta), np.sin(theta), color="#E69F00", alpha=0.45, lw=0)
    ax.fill(b * np.cos(theta), b * np.sin(theta), color="#56B4E9", alpha=0.7, lw=0)
    ax.plot(np.cos(theta), np.sin(theta), "k-", lw=1.0)
    ax.plot(b * np.cos(theta), b * np.sin(theta), "k--", lw=0.8)
    ax.annotate("", xy=(b * np.cos(0.6), b * np.sin(0.6)), xytext=(0, 0), arrowprops={"arrowstyle": "-|>", "lw": 0.8})
    ax.text(0.12, 0.28, "$b$", fontsize=9)
    a_angle = -np.pi / 6  # the radius a is drawn midway between two traction arrows, its label in the annulus
    ax.annotate("", xy=(np.cos(a_angle), np.sin(a_angle)), xytext=(0, 0), arrowprops={"arrowstyle": "-|>", "lw": 0.8})
    ax.text(0.8 * np.cos(a_angle) + 0.05, 0.8 * np.sin(a_angle) + 0.07, "$a$", fontsize=9, ha="center",
            va="center")
    ax.text(-0.33, -0.08, "stick", fontsize=8)
    ax.text(-0.76, 0.78, "slip", fontsize=8, ha="right")  # outside the circle
    # the friction traction f p0 on the annulus, 12 arrows offset by half their spacing from the radius a
    for angle in np.linspace(0, 2 * np.pi, 12, endpoint=False) + np.pi / 12:
        x, y = 0.8 * np.cos(angle), 0.8 * np.sin(angle)
        ax.annotate("", xy=(x - 0.16 * np.sin(angle), y + 0.16 * np.cos(angle)), xytext=(x, y),
                    arrowprops={"arrowstyle": "-|>", "lw": 0.7, "color": "0.25"})
    ax.set_xlim(-1.25, 1.25)
    ax.set_ylim(-1.25, 1.25)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title(r"(b) interface: $|\sigma_{\theta z}| = f p_0$ on $b < r < a$", fontsize=9)


def main():
    p = figure_parser(__doc__)
    p.add_argument("--stick-radius", type=float, required=True, help="b/a drawn in the plan view")
    a = p.parse_args()
    use_style(a.style)
    fig, (left, right) = subplots(1, 2, figsize=(6.0, 3.3), gridspec_kw={"width_ratios": [1.0, 1.1]})
    side_view(left)
    plan_view(right, a.stick_radius)
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
