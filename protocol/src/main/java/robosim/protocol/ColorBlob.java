package robosim.protocol;

/**
 * One connected region of an ACTS channel's colour in the camera's image, as ARIA's
 * {@code ArACTSBlob} reports it. Pixels count from the image's top left corner: x from 0 to
 * {@value CameraView#IMAGE_WIDTH} − 1 to the right, y from 0 to {@value CameraView#IMAGE_HEIGHT} − 1
 * down.
 *
 * @param channel the ACTS channel, 1 to {@value CameraView#CHANNELS}
 * @param area    pixels in the region
 * @param xcg     the column of its centre of gravity, rounded
 * @param ycg     the row of its centre of gravity, rounded
 * @param left    its leftmost column
 * @param right   its rightmost column
 * @param top     its topmost row
 * @param bottom  its lowest row
 */
public record ColorBlob(int channel, int area, int xcg, int ycg, int left, int right, int top, int bottom) { }
