# Sources of the contact analyzer and the resistance laws.
