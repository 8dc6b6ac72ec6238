/**
 * The robots a RemoteControl drives: {@link robosim.remote.robot.PioneerRemote} (an {@code ArRobot}
 * with a laser and a heat sensor) and {@link robosim.remote.robot.ScoutRemote} (a Nomadic Scout),
 * each a {@link robosim.remote.DriveTarget} whose {@link robosim.remote.robot.RemoteRobot#run()}
 * takes the robot's readings and messages once a step. No Swing here.
 */
package robosim.remote.robot;
