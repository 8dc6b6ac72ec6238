package robosim.viewer.view3d;

import java.awt.Color;

/**
 * One flat polygon of the scene, with its outward normal and colour, and optionally a mark drawn
 * on it (a robot's heading) and an outline colour (a stalled robot's).
 *
 * @param xyz     the corners x0, y0, z0, x1, y1, z1, ... in mm
 * @param normal  the outward unit normal
 * @param base    its colour before shading
 * @param mark    a polygon drawn on the face in a dark colour, x, y, z as {@code xyz}, or null
 * @param outline the colour of its outline, or null for none
 */
record Face(double[] xyz, double[] normal, Color base, double[] mark, Color outline) {
    /** @return the depth of the face's centre: how near it is to the camera */
    double depth(Projection p) {
        double sum = 0;
        int n = xyz.length / 3;
        for (int i = 0; i < xyz.length; i += 3) {
            sum += p.depth(xyz[i], xyz[i + 1], xyz[i + 2]);
        }
        return sum / n;
    }
}
