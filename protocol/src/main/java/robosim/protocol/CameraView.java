package robosim.protocol;

import java.util.List;

/**
 * What a robot's pan-tilt-zoom camera reports each step: where it points and, while ACTS tracks
 * colours, the blobs of each bound channel in its {@value #IMAGE_WIDTH} × {@value #IMAGE_HEIGHT} image.
 *
 * @param model the camera
 * @param pan   degrees, positive to the right as in ARIA's ArPTZ.h, where the camera is now (it moves at its own speed)
 * @param tilt  degrees, positive up
 * @param zoom  the camera's zoom units
 * @param blobs the blobs by channel, then largest first, at most {@value #MAX_BLOBS} per channel;
 *              empty when colours are not tracked
 */
public record CameraView(PtzModel model, double pan, double tilt, int zoom, List<ColorBlob> blobs) {
    /** Its key: the camera's part of a robot's state; absent (the camera off) reads as null. */
    public static final StatePart<CameraView> PART = StatePart.of("camera", CameraView.class);

    /** The image's width, pixels: ACTS's 160 × 120 frame. */
    public static final int IMAGE_WIDTH = 160;
    /** The image's height, pixels. */
    public static final int IMAGE_HEIGHT = 120;
    /** ACTS's channels, numbered from 1 (ARIA's {@code ArACTS_1_2::NUM_CHANNELS}). */
    public static final int CHANNELS = 32;
    /** The most blobs ACTS reports on one channel (ARIA's {@code ArACTS_1_2::MAX_BLOBS}). */
    public static final int MAX_BLOBS = 10;

    /** Copies the list so the record stays immutable. */
    public CameraView {
        blobs = blobs == null ? List.of() : List.copyOf(blobs);
    }
}
