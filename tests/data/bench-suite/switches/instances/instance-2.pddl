(define (problem a-only) (:domain switches) (:init) (:goal (and (on-a) (not (locked)))))
