package dev.crt.scene;

/** The set operations of constructive solid geometry, with their script operators. */
public enum CsgOperation {
    UNION("+"), INTERSECTION("^"), DIFFERENCE("-");

    private final String operator;

    CsgOperation(String operator) { this.operator = operator; }

    public String operator() { return operator; }
}
