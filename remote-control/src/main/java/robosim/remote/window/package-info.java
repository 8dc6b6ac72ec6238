/**
 * The RemoteControl's window, thin Swing over the {@link robosim.remote} model: the drive panel
 * (buttons, sliders, move and heading fields, sensor switches), the send box, the readings (a polar
 * plot of the sonar ring and laser scan, pose, velocities, stall, messages received), the robot's
 * parameters, and the embedded 2D view following the robot.
 */
package robosim.remote.window;
