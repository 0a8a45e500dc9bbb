/**
 * JEcoSys core: the meadow's simulation without any rendering (math, wind, plants, terrain, the
 * force field, animation, the simulation facade and the XML scene format). Exports the API packages
 * only; {@code org.jecosys.sim.internal} (frame and decision writers for tools and tests) is not
 * exported. The jar works on the class path as well.
 */
module org.jecosys.core {
    requires transitive org.joml;
    requires com.fasterxml.jackson.dataformat.xml;
    requires java.xml;
    requires java.desktop;
    requires java.management;
    requires jdk.management;

    exports org.jecosys.math;
    exports org.jecosys.wind;
    exports org.jecosys.plant;
    exports org.jecosys.terrain;
    exports org.jecosys.world;
    exports org.jecosys.field;
    exports org.jecosys.anim;
    exports org.jecosys.sim;
    exports org.jecosys.scene;
}
