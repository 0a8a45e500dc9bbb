package org.jecosys.bench;

/** How long a benchmark run may take. */
public enum Mode {
    /** Seconds: tiny sizes, for the smoke tests inside {@code mvn -B verify}; numbers mean nothing. */
    SMOKE,
    /** About 3 minutes on 2 cores: {@code jecosys bench --quick}. */
    QUICK,
    /** About 20 minutes on 2 cores: {@code jecosys bench}. */
    FULL
}
