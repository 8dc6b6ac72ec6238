package robosim.env.net;

/**
 * Why the step loop ends the run: how, for machines, and in words, for people.
 *
 * @param ending how it ended
 * @param reason the same in words, with the details, such as {@code step limit 400 reached}
 */
record EndOfRun(RunEnding ending, String reason) {
}
