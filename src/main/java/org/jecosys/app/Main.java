package org.jecosys.app;

/** Entry point placeholder (replaced by the CLI in this same change). */
public final class Main {
    private Main() {
    }

    public static void main(String[] args) {
        System.out.println("jecosys");
    }
}
