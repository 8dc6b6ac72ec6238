/**
 * The RemoteControl's model: what the window's buttons, keys, sliders and fields send to the robot
 * ({@link robosim.remote.RemoteControl}, {@link robosim.remote.KeyDrive}), the bounds they are
 * checked against ({@link robosim.remote.SpeedLimits}, {@link robosim.remote.DriveFields}), and what
 * the readings and parameters panels show ({@link robosim.remote.Readings},
 * {@link robosim.remote.ReadingLines}, {@link robosim.remote.ParameterRows}). No Swing or AWT here,
 * so all of it is tested headless; the robot behind it is a {@link robosim.remote.DriveTarget}.
 */
package robosim.remote;
