package robosim.aria;

/**
 * One blob of an ACTS channel, as ARIA's {@code ArACTSBlob} (ArACTS.h): its area in pixels, centre
 * of gravity and bounding box in the 160 × 120 image, x to the right and y down from the top left.
 * {@link ArACTS_1_2#getBlob} fills it in.
 */
public final class ArACTSBlob {
    private int area;
    private int xcg;
    private int ycg;
    private int left;
    private int right;
    private int top;
    private int bottom;

    /** @return pixels the blob covers */
    public int getArea() {
        return area;
    }

    /** @return the column of its centre of gravity */
    public int getXCG() {
        return xcg;
    }

    /** @return the row of its centre of gravity */
    public int getYCG() {
        return ycg;
    }

    /** @return its leftmost column */
    public int getLeft() {
        return left;
    }

    /** @return its rightmost column */
    public int getRight() {
        return right;
    }

    /** @return its topmost row */
    public int getTop() {
        return top;
    }

    /** @return its lowest row */
    public int getBottom() {
        return bottom;
    }

    /** @param area pixels */
    public void setArea(int area) {
        this.area = area;
    }

    /** @param xcg column */
    public void setXCG(int xcg) {
        this.xcg = xcg;
    }

    /** @param ycg row */
    public void setYCG(int ycg) {
        this.ycg = ycg;
    }

    /** @param left column */
    public void setLeft(int left) {
        this.left = left;
    }

    /** @param right column */
    public void setRight(int right) {
        this.right = right;
    }

    /** @param top row */
    public void setTop(int top) {
        this.top = top;
    }

    /** @param bottom row */
    public void setBottom(int bottom) {
        this.bottom = bottom;
    }

    @Override
    public String toString() {
        return "Area: " + area + " X: " + xcg + " Y: " + ycg + " l: " + left + " r: " + right + " t: " + top
                + " b: " + bottom;
    }
}
