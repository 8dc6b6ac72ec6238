/**
 * Robot parameter files: the record that travels to the Environment and the readers of ARIA's
 * {@code .p} form.
 */
package robosim.protocol.params;
