/**
 * Recordings of runs: the world once, then one record per step, in a versioned, compact, checked
 * file format (see {@link robosim.protocol.recording.RecordingFormat} and docs/VIEWER.md).
 *
 * <p>The Environment writes one with a {@link robosim.protocol.recording.RecordingWriter}
 * attached as a {@link robosim.protocol.recording.SnapshotListener}; a viewer can write the same from
 * what it receives. A {@link robosim.protocol.recording.RecordingReader} reads one back step by
 * step without an Environment, and reads a damaged file up to its last good record.
 */
package robosim.protocol.recording;
