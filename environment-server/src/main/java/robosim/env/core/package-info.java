/**
 * The simulation core: world state, differential-drive kinematics with ARIA's motion modes,
 * collisions and sonar. Plain deterministic Java, stepped by the server or by a test.
 */
package robosim.env.core;
