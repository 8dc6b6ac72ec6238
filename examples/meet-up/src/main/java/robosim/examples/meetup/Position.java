package robosim.examples.meetup;

/**
 * The message a {@link MeetUp} robot sends its peer: where it is. Any record Jackson can write as
 * JSON can be sent this way.
 *
 * @param x mm
 * @param y mm
 */
public record Position(double x, double y) {
}
