/**
 * The Scout Robot-Object: the Nomadic client library's calls ({@code connect_robot}, {@code vm},
 * {@code pr}, {@code gs}, {@code conf_sn}, the {@code State} vector, ...) with their names and units
 * (1/10 inch, 1/10 degree), over RoboSim's hardware simulator. {@link robosim.scout.Scout} is one
 * robot as an object; {@link robosim.scout.Nomad} mirrors the C library's global functions for a
 * program that drives one robot; {@link robosim.scout.StateVector} names the state vector's entries
 * and {@link robosim.scout.NomadUnits} converts the units.
 */
package robosim.scout;
